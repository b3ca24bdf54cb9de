# Request: a desk rack for Dupont jumper wires, 3 mm clear acrylic. A shelf 200 mm between two
# end uprights and 50 mm deep, its top 120 mm above the desk, with nine 2 mm slots cut 30 mm
# deep from its front edge, in three groups of three (slots 15 mm apart, groups 60 mm apart,
# centred); the wires drop into the slots and hang by their plug housings. Each group is
# labelled behind its slots, engraved 5 mm: "M-M", "M-F", "F-F". The uprights are 60 x 130 mm
# with 8 mm rounded top corners and a 30 mm finger hole 45 mm up; the shelf is glued into
# them by two 10 mm tabs at each end.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
shelf_w = 200 mm
shelf_d = 50 mm
shelf_top = 120 mm
names = ["M-M", "M-F", "F-F"]

def upright() -> solid {
    body = RoundedRectangle(bottom_left=(-30, 0), width=60, height=130,
                            corner_radii=[8, 8, 0, 0])
    hole finger { c = Circle(center=(0, 45), diameter=30) }
    # the shelf (local y shelf_top - t .. shelf_top) passes through here
    mortise = tab_and_slot(part="slot", length=shelf_d, thickness=t, tabs=2, tab=10 mm,
                           screw=0, cx=0 mm, cy=shelf_top - t / 2)
}

assembly rack {
    solid shelf {
        # tip to tip: the tabs stand t out past each upright's inner face
        board = Rectangle(center=(0, 0), width=shelf_w + 2 * t, height=shelf_d)
        left_tabs = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=10 mm,
                                 screw=0, rotation=90 deg, cx=-shelf_w / 2 - t, cy=0 mm)
        right_tabs = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=10 mm,
                                  screw=0, rotation=-90 deg, cx=shelf_w / 2 + t, cy=0 mm)
        hole slots {
            for g in range(3) {
                for j in range(3) {
                    s = Slot(start=((g - 1) * 60 mm + (j - 1) * 15 mm, -shelf_d / 2 - 2),
                             end=((g - 1) * 60 mm + (j - 1) * 15 mm, -shelf_d / 2 + 29),
                             width=2)
                }
            }
        }
        drawing labels {
            for g in range(3) {
                name = Text(names[g], position=((g - 1) * 60 mm, shelf_d / 2 - 10), size=5,
                            valign="middle")
            }
        }
    }
    left = upright()
    right = upright()
    RightOf(left, shelf, gap=10)
    RightOf(right, left, gap=10)
    AlignBottom(left, shelf)
    AlignBottom(right, shelf)

    # stood up: the uprights in the y-z plane at each end, the shelf between them
    Place(shelf, position=(0, 0, shelf_top - t))
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-shelf_w / 2 - t, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(shelf_w / 2, 0, 0))

    assert shelf.board.bb.width - 2 * t == 200 mm, "200 between the uprights"
    assert shelf.board.bb.height == 50 mm, "50 deep"
    assert len(shelf.slots.s) == 3 and len(shelf.slots.s[0]) == 3, "nine slots"
    assert shelf.slots.s[0][0].width == 2 mm, "2 mm slots"
    assert shelf.slots.s[1][1].bb.top - shelf.board.bb.bottom == 30 mm, "30 deep"
    assert shelf.slots.s[0][1].center.x - shelf.slots.s[0][0].center.x == 15 mm, "15 apart"
    assert shelf.slots.s[1][0].center.x - shelf.slots.s[0][0].center.x == 60 mm, "groups 60 apart"
    assert left.body.bb.width == 60 mm and left.body.bb.height == 130 mm, "uprights 60 x 130"
    assert left.mortise.bb.top - left.body.bb.bottom == 120 mm, "shelf top 120 up"
    assert left.finger.c.center.y - left.body.bb.bottom == 45 mm, "finger hole 45 up"
    assert shelf.labels.bb.bottom > shelf.slots.bb.top, "labels behind the slots"
}
