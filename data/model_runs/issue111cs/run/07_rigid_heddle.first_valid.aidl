# Request (crafts): a rigid heddle for a 250 mm lap loom, 3 mm acrylic, with its two heddle
# blocks in 6 mm plywood. Heddle: 266 x 120 mm with 8 mm rounded corners and an ear at each end
# (to 300 mm overall, 40 mm tall) that rests in the blocks; 24 slots 2.5 x 60 mm, 10 mm apart,
# and a 2.5 mm hole in the middle of each of the 23 bars between them (2 ends per cm); an
# 80 x 14 mm hand grip in the top bar; "2 ENDS PER CM" engraved in the bottom bar (5 mm).
# Blocks: 50 x 80 mm, screwed to the loom's sides with two countersunk M4 screws (8 mm heads);
# two notches from the top, 3.4 mm wide (heddle + 0.4 mm): "UP" 20 mm deep, "DN" 45 mm deep,
# each labelled (4 mm engraved letters). Inside the loom the blocks are 280 mm apart.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 3 mm

param t = 3 mm, min = 2 mm, max = 5 mm
param slots = 24, min = 10, max = 40
param pitch = 10 mm, min = 6 mm, max = 16 mm

def heddle_block() -> solid {
    thickness 6 mm
    body = Rectangle(center=(0, 0), width=50, height=80)
    up = cross_halving(depth=20 mm, thickness=t, clearance=0.4 mm, cx=-10 mm, cy=40 mm)
    down = cross_halving(depth=45 mm, thickness=t, clearance=0.4 mm, cx=10 mm, cy=40 mm)
    screw_a = clearance_hole(size=4, cx=-12 mm, cy=-12 mm)
    screw_b = clearance_hole(size=4, cx=-12 mm, cy=-30 mm)
    Countersink([screw_a, screw_b], diameter=8 mm)
    drawing labels {
        u = Text("UP", position=(-10, 14), size=4, valign="middle")
        d = Text("DN", position=(10, -12), size=4, valign="middle")
    }
}

assembly rigid_heddle {
    solid heddle {
        board = RoundedRectangle(center=(0, 0), width=266, height=120, corner_radius=8)
        ears = Rectangle(center=(0, 0), width=300, height=40)
        hole slot { s = Slot(center=(-(slots - 1) * pitch / 2, 0), length=60, width=2.5,
                             rotation=90 deg) }
        slot_row = LinearPattern(slot, slots, (pitch, 0))
        hole eye { c = Circle(center=(-(slots - 2) * pitch / 2, 0), diameter=2.5) }
        eye_row = LinearPattern(eye, slots - 1, (pitch, 0))
        hole grip { g = Slot(center=(0, 45), length=80, width=14) }
        drawing mark { m = Text("2 ENDS PER CM", position=(0, -45), size=5, valign="middle") }
    }

    block_l = heddle_block()
    block_r = heddle_block()

    # flat on the sheet
    RightOf(block_l, heddle, gap=6)
    AlignTop(block_l, heddle)
    RightOf(block_r, block_l, gap=6)
    AlignTop(block_r, heddle)

    # assembled: blocks upright on the loom's sides (inner faces 280 mm apart), the heddle
    # standing across the warp in the deep notches, its ears resting on the notches' bottoms
    Place(block_l, position=(-146, 0, 40), face="right", up="up")
    Place(block_r, position=(140, 0, 40), face="right", up="up")
    Place(heddle, position=(0, 10 + t / 2, 80 - 45 + 20), face="front", up="up")

    # the request's numbers
    assert heddle.board.bb.width == 266 mm and heddle.board.bb.height == 120 mm
    assert heddle.ears.bb.width == 300 mm and heddle.ears.bb.height == 40 mm
    assert len(heddle.slot_row) == 24 and len(heddle.eye_row) == 23
    assert heddle.slot_row[1].s.center.x - heddle.slot_row[0].s.center.x == 10 mm
    assert heddle.slot.s.width == 2.5 mm and heddle.slot.s.length == 60 mm
    assert heddle.eye.c.diameter == 2.5 mm
    # each hole in the middle of its bar
    assert heddle.eye_row[0].c.center.x - heddle.slot_row[0].s.center.x == 5 mm
    assert heddle.eye_row[22].c.center.x - heddle.slot_row[22].s.center.x == 5 mm
    assert heddle.grip.g.length == 80 mm and heddle.grip.g.width == 14 mm
    assert heddle.mark.m.size == 5 mm
    assert block_l.body.bb.width == 50 mm and block_l.body.bb.height == 80 mm
    assert block_l.up.depth == 20 mm and block_l.down.depth == 45 mm
    assert block_l.up.cut.bb.width == 3.4 mm
    # the grip and the label stay on the bars, clear of the slots
    assert heddle.grip.g.bb.bottom - heddle.slot.s.bb.top >= 5 mm
    assert heddle.slot.s.bb.bottom - heddle.mark.m.bb.top >= 5 mm
}
