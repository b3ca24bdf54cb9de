# Request (bathroom): a lipstick stand for the bathroom shelf, cut from 3 mm plywood and
# screwed together with M3 screws and captive nuts, four parts:
# - top plate 170 x 90 mm, corners R6, ten 24 mm holes for the lipsticks in 2 rows of 5,
#   28 mm apart along the rows and 30 mm between the rows, centred on the plate;
#   "ROSE'S LIPSTICKS" engraved (sans, 7 mm) centred in the strip in front of the holes.
# - bottom plate 170 x 90 mm, corners R6 (the lipsticks stand on it).
# - two legs, 90 mm deep, holding the plates 60 mm apart (inside), 10 mm in from the plates'
#   ends (their middles), each with two 15 mm tabs and an M3 T-slot at the top and at the
#   bottom, and a 50 x 20 mm slot-shaped window in the middle to lighten them.

units mm
thickness 3 mm
import "std/joints.aidl"

t = 3 mm
plate_w = 170 mm
plate_d = 90 mm
gap_in = 60 mm
leg_in = 10 mm
leg_h = gap_in + 2 * t

def joint_slots(x) -> hole {
    s = Circle(center=(x, 0), radius=1, construction=true)
}

assembly stand {
    solid top {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_d, corner_radius=6)
        hole tube {
            c = Circle(center=(-2 * 28 mm, -15 mm), diameter=24)
        }
        tubes = GridPattern(tube, 2, 5, (28, 30))
        left = tab_and_slot(part="slot", length=plate_d, thickness=t, tabs=2, tab=15 mm, screw=3,
                            rotation=90 deg, cx=-plate_w / 2 + leg_in, cy=0 mm)
        right = tab_and_slot(part="slot", length=plate_d, thickness=t, tabs=2, tab=15 mm, screw=3,
                             rotation=90 deg, cx=plate_w / 2 - leg_in, cy=0 mm)
        drawing label {
            words = Text("ROSE'S LIPSTICKS", position=(0, 0), size=7, font="sans", valign="middle")
        }
        # centred in the strip between the front edge and the front row of holes
        label.words.position.y == (body.bb.bottom + tubes[0].c.bb.bottom) / 2
        AlignCenterX(label, body)
    }

    solid bottom {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_d, corner_radius=6)
        left = tab_and_slot(part="slot", length=plate_d, thickness=t, tabs=2, tab=15 mm, screw=3,
                            rotation=90 deg, cx=-plate_w / 2 + leg_in, cy=0 mm)
        right = tab_and_slot(part="slot", length=plate_d, thickness=t, tabs=2, tab=15 mm, screw=3,
                             rotation=90 deg, cx=plate_w / 2 - leg_in, cy=0 mm)
    }

    for i in range(2) {
        solid leg {
            body = Rectangle(center=(0, 0), width=plate_d, height=leg_h)
            up = tab_and_slot(part="tab", length=plate_d, thickness=t, tabs=2, tab=15 mm, screw=3,
                              cx=0 mm, cy=leg_h / 2)
            down = tab_and_slot(part="tab", length=plate_d, thickness=t, tabs=2, tab=15 mm, screw=3,
                                rotation=180 deg, cx=0 mm, cy=-leg_h / 2)
            hole window {
                s = Slot(center=(0, 0), length=50, width=20)
            }
        }
    }

    RightOf(bottom, top, gap=10)
    AlignTop(bottom, top)
    Below(leg[0], top, gap=10)
    AlignLeft(leg[0], top)
    RightOf(leg[1], leg[0], gap=10)
    AlignTop(leg[1], leg[0])

    # the request's numbers
    assert top.body.width == 170 mm and top.body.height == 90 mm, "top 170 x 90"
    assert len(top.tubes) == 10, "ten lipstick holes"
    assert top.tubes[0].c.diameter == 24 mm, "holes 24 mm"
    assert top.tubes[1].c.center.x - top.tubes[0].c.center.x == 28 mm, "28 mm along the rows"
    assert top.tubes[5].c.center.y - top.tubes[0].c.center.y == 30 mm, "30 mm between rows"
    assert (top.tubes[0].c.center.x + top.tubes[9].c.center.x) / 2 == top.body.center.x, "holes centred in x"
    assert (top.tubes[0].c.center.y + top.tubes[9].c.center.y) / 2 == top.body.center.y, "holes centred in y"
    assert leg[0].body.width == 90 mm, "legs 90 mm deep"
    assert leg[0].body.height - 2 * 3 mm == 60 mm, "plates 60 mm apart inside"
    assert top.right.slot[0].center.x == top.body.bb.right - 10 mm, "legs 10 mm in"
}
