# Home: a bedside eyeglasses stand, two 4 mm plywood pieces cross-halved. Upright A: a body
# 100 mm wide and 90 mm tall with R20 top corners, and a nose on which the glasses' bridge
# rests: 24 mm wide, its round top (R12) 130 mm above A's bottom edge, centred. A smile: an arc
# slot 4 mm wide on a 20 mm radius about a point 45 mm above A's bottom, from 220 to 320 deg;
# "SPECS" engraved 10 mm high, centred, its middle 55 mm above the bottom. Foot B: 100 x 30 mm,
# with a shallow arch under it (a R40 circle centred 34 mm below B's bottom edge, i.e. 6 mm
# high). Cross halving: A slotted 15 mm up from the middle of its bottom edge, B 15 mm down from
# the middle of its top edge (15 + 15 = B's 30 mm), slots 4 mm + 0.1 mm clearance wide.
units mm
thickness 4 mm
import "std/joints.aidl"

assembly stand {
    solid a {
        body = RoundedRectangle(center=(0, 45), width=100, height=90, corner_radii=[20, 20, 0, 0])
        nose = RoundedRectangle(center=(0, 105), width=24, height=50, corner_radii=[12, 12, 0, 0])
        slot = cross_halving(depth=15 mm, thickness=4 mm, clearance=0.1 mm, rotation=180 deg, cx=0, cy=0)
        hole smile {
            s = ArcSlot(center=(0, 45), radius=20, start_angle=220 deg, end_angle=320 deg, width=4)
        }
        drawing label {
            word = Text("SPECS", (0, 55), size=10, valign="middle")
        }
    }
    solid b {
        body = Rectangle(center=(0, 15), width=100, height=30)
        slot = cross_halving(depth=15 mm, thickness=4 mm, clearance=0.1 mm, cx=0, cy=30)
        hole arch {
            c = Circle(center=(0, -34), radius=40)
        }
    }
    RightOf(b, a, gap=10)
    AlignBottom(b, a)

    assert a.body.bb.width == 100 mm and a.body.bb.height == 90 mm, "A's body 100 x 90"
    assert a.nose.bb.width == 24 mm, "nose 24 wide"
    assert a.nose.bb.top - a.body.bb.bottom == 130 mm, "nose top 130 above the bottom"
    assert a.nose.center.x == a.body.center.x, "nose centred"
    assert a.smile.s.radius == 20 mm and a.smile.s.width == 4 mm, "smile R20, 4 wide"
    assert a.smile.s.center.y - a.body.bb.bottom == 45 mm, "smile centre 45 up"
    assert a.label.word.size == 10 mm, "SPECS 10 mm"
    assert a.label.word.position.y - a.body.bb.bottom == 55 mm, "SPECS middle 55 up"
    assert b.body.bb.width == 100 mm and b.body.bb.height == 30 mm, "foot 100 x 30"
    assert b.arch.c.radius == 40 mm and b.body.bb.bottom - b.arch.c.center.y == 34 mm, "arch R40, centre 34 below"
    assert a.slot.cut.bb.height == 15 mm and b.slot.cut.bb.height == 15 mm, "15 + 15"
    assert a.slot.cut.bb.height + b.slot.cut.bb.height == b.body.bb.height, "depths add up to B's height"
    assert a.slot.cut.bb.width == 4.1 mm, "4 + 0.1 wide"
    assert a.slot.cut.bb.bottom == a.body.bb.bottom and b.slot.cut.bb.top == b.body.bb.top, "from the edges"
    assert a.slot.cut.bb.center_x == a.body.center.x and b.slot.cut.bb.center_x == b.body.center.x, "in the middles"
}
