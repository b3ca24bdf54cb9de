# Request (kitchen): an oven-rack push-pull stick, cut from 6 mm birch ply.
# A bar 300 mm long and 35 mm wide. The handle end (left) is fully rounded
# (R17.5) and has a 10 mm hanging hole centred in the round end. The working end
# (right) has square corners rounded R3, a push notch 8 mm wide and 12 mm deep
# cut into the end face on the centre line (round-bottomed, for the rack's wire),
# and a pull hook: a notch 8 mm wide and 14 mm deep cut down from the top edge,
# its centre line 30 mm from the working end. "OVEN RACK" engraved along the
# middle of the bar, 8 mm letters, centred between the hanging hole and the hook.

thickness 6 mm

param length = 300 mm, min = 200 mm, max = 400 mm
param width = 35 mm, min = 25 mm, max = 50 mm
notch_w = 8 mm
push_depth = 12 mm
hook_depth = 14 mm
hook_from_end = 30 mm
hang_d = 10 mm

solid stick {
    body = RoundedRectangle(center=(0, 0), width=length, height=width,
                            corner_radii=[width / 2, 3 mm, 3 mm, width / 2])

    # hanging hole, concentric with the rounded handle end
    hole hang {
        c = Circle(center=(-length / 2 + width / 2, 0), diameter=hang_d)
    }

    # push notch in the end face: a round-bottomed slot running out past the end
    hole push {
        s = Slot(start=(length / 2 - push_depth + notch_w / 2, 0), end=(length / 2 + 10 mm, 0),
                 width=notch_w, overrun=true)
    }

    # pull hook: a round-bottomed slot running up out of the top edge
    hole hook {
        s = Slot(start=(length / 2 - hook_from_end, width / 2 - hook_depth + notch_w / 2),
                 end=(length / 2 - hook_from_end, width / 2 + 10 mm), width=notch_w, overrun=true)
    }

    drawing label {
        word = Text("OVEN RACK", position=(0, 0), size=8, valign="middle")
    }

    AlignCenterY(label, body)
    label.word.position.x == (hang.c.center.x + hook.s.start.x) / 2

    assert body.bb.width == 300 mm, "bar 300 mm long"
    assert body.bb.height == 35 mm, "bar 35 mm wide"
    assert body.bb.right - (push.s.start.x - notch_w / 2) == 12 mm, "push notch 12 mm deep"
    assert push.s.width == 8 mm and hook.s.width == 8 mm, "notches 8 mm wide"
    assert body.bb.top - (hook.s.start.y - notch_w / 2) == 14 mm, "hook 14 mm deep"
    assert body.bb.right - hook.s.start.x == 30 mm, "hook 30 mm from the working end"
    assert hang.c.diameter == 10 mm, "10 mm hanging hole"
    assert hang.c.center.x - body.bb.left == 35 mm / 2, "hole centred in the round end"
}
