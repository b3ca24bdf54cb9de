# Workshop: a zero-clearance throat insert for my contractor table saw, cut from
# 6 mm MDF. Plate 320 x 90 mm with 20 mm corner radii. The blade slot is 3.5 mm
# wide and 130 mm long, on the centre line, its back end 70 mm from the back
# (right) end of the plate. A 22 mm finger hole on the centre line, its centre
# 40 mm from the front (left) end. Two M4 countersunk hold-down screw holes
# (4.5 mm, 9 mm heads) on the centre line, 12 mm in from each end. Four 5 mm
# levelling set-screw holes, 25 mm in from the ends and 15 mm in from the long
# edges. Engrave "ZERO CLEARANCE 3.5 KERF" (6 mm letters) 25 mm below the centre
# line, centred on the blade slot.

units mm
thickness 6 mm

param length = 320 mm, min = 250, max = 400
param width = 90 mm, min = 70, max = 120
param kerf_w = 3.5 mm, min = 2, max = 6
param slot_len = 130 mm, min = 60, max = 180

solid insert {
    body = RoundedRectangle(center=(0, 0), width=length, height=width, corner_radius=20)

    hole blade {
        s = Slot(center=(0, 0), length=slot_len, width=kerf_w)
    }
    AlignCenterY(blade, body)
    blade.bb.right == body.bb.right - 70 mm

    hole finger {
        c = Circle(center=(-120, 0), diameter=22)
    }
    AlignCenterY(finger, body)
    finger.c.center.x == body.bb.left + 40 mm

    hole screw {
        c = Circle(center=(-148, 0), diameter=4.5)
    }
    AlignCenterY(screw, body)
    screw.c.center.x == body.bb.left + 12 mm
    screws = LinearPattern(screw, 2, (length - 24 mm, 0))
    Countersink(screws, diameter=9)

    hole level {
        c = Circle(center=(-135, -30), diameter=5)
    }
    levels = CornerPattern(level, body, inset=(25, 15))

    drawing label {
        t = Text("ZERO CLEARANCE 3.5 KERF", position=(0, -25), size=6, valign="middle")
    }
    At(label.t.position, blade.s.center, dy=-25)

    assert body.bb.width == 320 mm, "plate 320 long"
    assert body.bb.height == 90 mm, "plate 90 wide"
    assert blade.s.width == 3.5 mm, "blade slot 3.5 wide"
    assert blade.bb.width == 130 mm, "blade slot 130 long"
    assert body.bb.right - blade.bb.right == 70 mm, "slot ends 70 from the back end"
    assert finger.c.center.x - body.bb.left == 40 mm, "finger hole 40 from the front"
    assert len(screws) == 2, "two hold-down screws"
    assert screws[1].c.center.x == body.bb.right - 12 mm, "back screw 12 in from the end"
    assert len(levels) == 4, "four levelling screws"
    assert levels[2].c.center.y == body.bb.top - 15 mm, "levelling screws 15 in from the edge"
    assert label.t.position.y == body.bb.center_y - 25 mm, "label 25 below the centre line"
}
