# Request (gifts): a watch stand for Father's Day, cut from 4 mm walnut plywood,
# two parts that slot together crosswise. The upright: 70 mm wide, 110 mm tall,
# its top a full half-round (R35) for the watch strap to wrap round, with a
# heart cut through it (34 mm wide, its point 29 mm above the bottom edge),
# centred left to right. The foot: 120 x 40 mm with R3 corners, standing on
# edge. They cross by a halving joint at the middle of each: a 20 mm slot up
# from the upright's bottom edge and a 20 mm slot down from the foot's top
# edge, 4 mm material plus 0.1 mm clearance, so both bottoms stand on the
# table. "TO DAD" and "2027" engraved (filled serif letters, 8 mm) centred on
# the foot's left and right wings, their middles 10 mm below the foot's middle.
# Laid out side by side to cut.

import "std/joints.aidl"

thickness 4 mm

up_w = 70 mm
up_h = 110 mm
foot_w = 120 mm
foot_h = 40 mm
halving = 20 mm
mat = 4 mm

assembly watch_stand {
    solid upright {
        body = RoundedRectangle(center=(0, 0), width=up_w, height=up_h,
                                corner_radii=[up_w / 2, up_w / 2, 0, 0])
        slot = cross_halving(depth=halving, thickness=mat, clearance=0.1 mm, rotation=180 deg,
                             cx=0 mm, cy=-up_h / 2)
        hole heart {
            left = Hull(Circle(center=(-8, -5), radius=9), Point(0, -26))
            right = Hull(Circle(center=(8, -5), radius=9), Point(0, -26))
        }
        AlignCenterX(heart, body)
        heart.bb.bottom == body.bb.bottom + 29 mm
    }

    solid foot {
        body = RoundedRectangle(center=(0, 0), width=foot_w, height=foot_h, corner_radius=3 mm)
        slot = cross_halving(depth=halving, thickness=mat, clearance=0.1 mm, cx=0 mm,
                             cy=foot_h / 2)
        drawing words {
            to = Text("TO DAD", position=(-31, -10), size=8, font="serif", valign="middle",
                      fill=true)
            year = Text("2027", position=(31, -10), size=8, font="serif", valign="middle",
                        fill=true)
        }
        # each word centred on its wing, between the end and the slot
        words.to.position.x == (body.bb.left + slot.cut.bb.left) / 2
        words.year.position.x == (slot.cut.bb.right + body.bb.right) / 2
        words.to.position.y == body.center.y - 10 mm
        words.year.position.y == body.center.y - 10 mm
    }

    RightOf(foot, upright, gap=8 mm)
    AlignBottom(foot, upright)

    assert upright.body.bb.width == 70 mm and upright.body.bb.height == 110 mm, "upright 70 x 110"
    assert foot.body.bb.width == 120 mm and foot.body.bb.height == 40 mm, "foot 120 x 40"
    assert upright.heart.bb.width == 34 mm, "heart 34 mm wide"
    assert upright.heart.bb.bottom - upright.body.bb.bottom == 29 mm, "heart point 29 up"
    assert upright.slot.cut.bb.height == 20 mm and foot.slot.cut.bb.height == 20 mm,
        "20 mm halving slots"
    assert upright.slot.cut.bb.height + foot.slot.cut.bb.height == foot.body.bb.height,
        "both bottoms on the table"
    assert foot.slot.cut.bb.width == 4.1 mm, "4 mm + 0.1 mm clearance"
}
