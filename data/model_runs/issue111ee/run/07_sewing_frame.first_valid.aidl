# Request (crafts): a bookbinding sewing frame, for sewing signatures onto tapes or cords.
# 6 mm ply, glued.
# - A base 300 x 180 mm. A sewing slot 220 mm long x 10 mm wide (round ends) across it, 20 mm
#   behind the base's centre line, right under the crossbar, for the cords to pass through to
#   their keys underneath. Four M4 holes for screw-on rubber feet, 15 mm in from each corner,
#   to lift it for the keys.
# - A mm scale engraved along the front of the slot, centred on the middle: a tick every 10 mm
#   (6 mm long every 20 mm, 3 mm between), numbered every 20 mm from 0 in the middle, 3 mm text.
# - Two uprights 40 mm wide, 260 mm apart (centre to centre), standing in the base on two 10 mm
#   tenons each; their tops 260 mm above the base.
# - A crossbar 300 mm long x 40 mm high, flush with the uprights' tops, joined to them by cross
#   halvings (uprights slotted 30 mm, crossbar 10 mm). Five 4 mm cord holes in it, 40 mm apart,
#   centred.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm
t = 6 mm

span = 260 mm         # uprights, centre to centre
sew_y = 20 mm         # the slot and the crossbar's plane, behind the base's centre line
top = 260 mm          # uprights' and crossbar's top, above the base
def tick_x(i) = -110 mm + i * 10 mm

assembly sewing_frame {
    solid base {
        body = Rectangle(center=(0, 0), width=300, height=180)
        hole sewing_slot { s = Slot(center=(0, sew_y), length=220, width=10) }
        left_mortise = tab_and_slot(part="slot", length=40, thickness=t, tabs=2, tab=10, screw=0,
                                    rotation=90 deg, cx=-span / 2, cy=sew_y)
        right_mortise = tab_and_slot(part="slot", length=40, thickness=t, tabs=2, tab=10, screw=0,
                                     rotation=90 deg, cx=span / 2, cy=sew_y)
        foot = clearance_hole(size=4)
        feet = CornerPattern(foot, body, inset=15)
        drawing scale {
            for i in range(23) {
                tick = Line((tick_x(i), sew_y - 7), (tick_x(i), sew_y - 7 - (6 if i % 2 == 1 else 3)))
            }
            for j in range(11) {
                num = Text(str(abs(-100 + j * 20)), position=(-100 mm + j * 20 mm, sew_y - 18.5),
                           size=3)
            }
        }
    }

    def upright() -> solid {
        body = Rectangle(bottom_left=(-20, -t), width=40, height=top + t)
        tenons = tab_and_slot(part="tab", length=40, thickness=t, tabs=2, tab=10, screw=0,
                              rotation=180 deg, cx=0, cy=-t)
        halving = cross_halving(depth=30 mm, thickness=t, cx=0, cy=top)
    }
    left = upright()
    right = upright()

    solid crossbar {
        body = Rectangle(bottom_left=(-150, top - 40), width=300, height=40)
        left_halving = cross_halving(depth=10 mm, thickness=t, rotation=180 deg, cx=-span / 2,
                                     cy=top - 40)
        right_halving = cross_halving(depth=10 mm, thickness=t, rotation=180 deg, cx=span / 2,
                                      cy=top - 40)
        hole cords {
            for k in range(5) {
                c = Circle(center=(-80 + k * 40, top - 20), diameter=4)
            }
        }
    }

    # flat on the sheet
    RightOf(left, base, gap=5)
    AlignBottom(left, base)
    RightOf(right, left, gap=5)
    AlignBottom(right, base)
    Below(crossbar, base, gap=5)
    AlignLeft(crossbar, base)

    # assembled: base flat; uprights across x at x = -130 / 130; crossbar in the plane y = sew_y
    Place(base, position=(0, 0, 0))
    Place(left, position=(-span / 2 - t / 2, sew_y, t), face="right", up="up")
    Place(right, position=(span / 2 - t / 2, sew_y, t), face="right", up="up")
    Place(crossbar, position=(0, sew_y + t / 2, t), face="front", up="up")

    assert base.body.bb.width == 300 mm and base.body.bb.height == 180 mm, "base 300 x 180"
    assert base.sewing_slot.s.length == 220 mm and base.sewing_slot.s.width == 10 mm, "slot 220 x 10"
    assert base.sewing_slot.s.center.y - base.body.center.y == 20 mm, "slot 20 behind the middle"
    assert base.right_mortise.slot[0].bb.center_x - base.left_mortise.slot[0].bb.center_x == 260 mm,
        "uprights 260 apart"
    assert left.body.bb.height - t == 260 mm, "uprights' tops 260 up"
    assert crossbar.body.bb.width == 300 mm and crossbar.body.bb.height == 40 mm, "crossbar 300 x 40"
    assert crossbar.cords.c[1].center.x - crossbar.cords.c[0].center.x == 40 mm, "cords 40 apart"
    assert len(feet) == 4, "four feet"
    assert feet[0].c.center.x - base.body.bb.left == 15 mm, "feet 15 in"
    assert len(base.scale.tick) == 23, "a tick every 10 mm over the slot"
}
