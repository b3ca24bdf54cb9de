# Request (camping): an organiser that threads onto a camping hammock's ridgeline to hang a
# headlamp, glasses and a phone pouch, cut from 6 mm ply.
# - a plate 220 mm long and 45 mm tall at its ends, its top edge one arc rising to 60 mm at
#   the middle; the bottom corners rounded 6 mm.
# - two 8 mm holes for the ridgeline, centred 15 mm in from each end and 33 mm above the
#   bottom edge.
# - along the bottom edge five hook notches 40 mm apart, centred on the plate: each a slot
#   6 mm wide rising from the bottom edge into a round eye 10 mm across, whose centre is
#   14 mm above the bottom edge; the slot's mouth corners rounded 2 mm so a loop slides in.
# - "RIDGELINE" engraved in strokes 8 mm tall, centred, its middle 38 mm above the bottom.

units mm
thickness 6 mm

len_ = 220 mm
end_h = 45 mm
mid_h = 60 mm
hooks = 5
hook_pitch = 40 mm

solid organiser {
    solid plate {
        bottom = Line((-len_ / 2, 0), (len_ / 2, 0))
        right = Line((len_ / 2, 0), (len_ / 2, end_h))
        top = Arc(start=(len_ / 2, end_h), through=(0, mid_h), end=(-len_ / 2, end_h))
        left = Line((-len_ / 2, end_h), (-len_ / 2, 0))
    }

    hole line_holes {
        l = Circle(center=(-len_ / 2 + 15, 33), diameter=8)
        r = Circle(center=(len_ / 2 - 15, 33), diameter=8)
    }

    hole hook {
        mouth = Rectangle(corner=(-hook_pitch * (hooks - 1) / 2 - 3, -1),
                          opposite=(-hook_pitch * (hooks - 1) / 2 + 3, 14))
        eye = Circle(center=(-hook_pitch * (hooks - 1) / 2, 14), diameter=10)
    }
    hook_row = LinearPattern(hook, hooks, (hook_pitch, 0))

    drawing label {
        word = Text("RIDGELINE", position=(0, 38), size=8, valign="middle")
    }

    Fillet([(-len_ / 2, 0), (len_ / 2, 0)], 6)
    Fillet([(-hook_pitch * (hooks - 1) / 2 - 3 + i * hook_pitch, 0) for i in range(hooks)] +
           [(-hook_pitch * (hooks - 1) / 2 + 3 + i * hook_pitch, 0) for i in range(hooks)], 2)

    assert plate.bb.width == 220 mm, "220 mm long"
    assert plate.right.length == 45 mm, "45 mm tall at the ends"
    assert plate.top.through.y - plate.bottom.start.y == 60 mm, "60 mm at the middle"
    assert line_holes.l.center.x - plate.bb.left == 15 mm, "holes 15 mm in from the ends"
    assert plate.bb.right - line_holes.r.center.x == 15 mm, "holes 15 mm in from the ends"
    assert line_holes.l.center.y - plate.bottom.start.y == 33 mm, "holes 33 mm up"
    assert len(hook_row) == 5, "five hooks"
    assert hook_row[1].eye.center.x - hook_row[0].eye.center.x == 40 mm, "40 mm apart"
    assert hook_row[2].eye.center.x == plate.top.through.x, "centred on the plate"
    assert hook_row[0].eye.center.y - plate.bottom.start.y == 14 mm, "eyes 14 mm up"
    assert hook_row[0].mouth.width == 6 mm and hook_row[0].eye.diameter == 10 mm
    assert distance(label, line_holes) >= 3 mm and distance(label, hook) >= 3 mm
    assert distance(line_holes, hook_row) >= 5 mm, "material between holes and hooks"
}
