# Request (science): a classroom kit for the "simplest electric motor" (a wire coil spinning
# over a magnet), cut from 6 mm ply, glued tab and slot.
# - Base 140 x 90 mm, corners rounded 5 mm. Near its back, the coil's axis runs left-right
#   20 mm behind the base's middle; two uprights stand across it with 40 mm between their
#   inner faces. Under the coil, centred between the uprights, an engraved 25 mm circle marks
#   where the magnet goes, with an engraved "N" in it (5 mm). At the front, two 4.2 mm holes
#   for M4 terminal screws 100 mm apart, 25 mm in front of the middle, with "+" (left) and "-"
#   (right) engraved 8 mm above them in 6 mm characters, and "SIMPLE MOTOR" engraved filled
#   in 7 mm bold letters between them.
# - Two uprights 40 mm wide, standing 35 mm above the base's top face, top corners rounded
#   8 mm, each with two 12 mm tabs down into the base and a U-notch 2 mm wide in the middle
#   of the top where the coil's wire axle rests, 25 mm above the base's top face.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
gap_in = 40 mm         # between the uprights' inner faces
axis_y = 20 mm         # the coil's axis behind the base's middle
axle_h = 25 mm         # the axle above the base's top face
stand_h = 35 mm        # the uprights above the base's top face

def upright() -> solid {
    body = RoundedRectangle(bottom_left=(-20, 0), width=40, height=stand_h + t,
                            corner_radii=[8, 8, 0, 0])
    feet = tab_and_slot(part="tab", length=40, thickness=t, tabs=2, tab=12, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    hole notch {
        u = Slot(start=(0, t + axle_h + 1), end=(0, t + stand_h + 5), width=2)
    }
}

assembly motor_kit {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=140, height=90, corner_radius=5)
        left_slot = tab_and_slot(part="slot", length=40, thickness=t, tabs=2, tab=12, screw=0,
                                 rotation=90 deg, cx=-(gap_in + t) / 2, cy=axis_y)
        right_slot = tab_and_slot(part="slot", length=40, thickness=t, tabs=2, tab=12, screw=0,
                                  rotation=90 deg, cx=(gap_in + t) / 2, cy=axis_y)
        hole terminals {
            minus_h = Circle(center=(50, -25), diameter=4.2)
            plus_h = Circle(center=(-50, -25), diameter=4.2)
        }
        drawing marks {
            magnet = Circle(center=(0, axis_y), diameter=25)
            n = Text("N", position=(0, axis_y), size=5, valign="middle")
            plus = Text("+", position=(-50, -25 + 8), size=6, valign="middle")
            minus = Text("-", position=(50, -25 + 8), size=6, valign="middle")
        }
        drawing title {
            w = Text("SIMPLE MOTOR", position=(0, -25), size=7, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    for i in range(2) {
        stands = upright()
    }

    RightOf(stands[0], base, gap=10)
    AlignBottom(stands[0], base)
    RightOf(stands[1], stands[0], gap=10)
    AlignBottom(stands[1], stands[0])

    assert base.body.bb.width == 140 mm and base.body.bb.height == 90 mm
    assert base.right_slot.slot[0].bb.left - base.left_slot.slot[0].bb.right == 40 mm
    assert base.right_slot.bb.center_y - base.body.bb.center_y == 20 mm
    assert base.marks.magnet.center.x == (base.right_slot.slot[0].bb.center_x + base.left_slot.slot[0].bb.center_x) / 2
    assert base.terminals.minus_h.center.x - base.terminals.plus_h.center.x == 100 mm
    assert base.body.bb.center_y - base.terminals.plus_h.center.y == 25 mm
    assert base.marks.plus.position.y - base.terminals.plus_h.center.y == 8 mm
    assert base.marks.plus.position.x < base.marks.minus.position.x, "+ on the left"
    assert distance(base.title, base.terminals) >= 3 mm
    assert distance(base.marks.magnet, base.left_slot) >= 3 mm
    assert stands[0].notch.u.bb.bottom - (stands[0].body.bb.bottom + t) == 25 mm
    assert stands[0].body.bb.height - t == 35 mm
}
