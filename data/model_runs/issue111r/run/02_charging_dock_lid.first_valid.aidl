# Home charging-station lid: a 3 mm plate 200 x 120 mm with 8 mm corner radii; three
# cable slots 6 mm wide x 20 mm long (vertical), 50 mm apart, centred left-right, their
# centres 35 mm below the top edge; "CHARGE" engraved 8 mm tall, its baseline 20 mm
# above the bottom edge, centred; four 4 mm screw holes 10 mm in from each corner,
# countersunk to 9 mm.
thickness 3 mm

param w = 200 mm, min = 150 mm, max = 300 mm
param h = 120 mm, min = 90 mm, max = 200 mm
param pitch = 50 mm, min = 30 mm, max = 70 mm

solid lid {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=8)

    hole cable {
        s = Slot(center=(0, 0), length=20, width=6, rotation=90)
    }
    cables = LinearPattern(cable, 3, (pitch, 0))
    AlignCenterX(cables[1], body)
    cable.s.center.y == body.bb.top - 35 mm

    hole screw {
        c = Circle(center=(0, 0), diameter=4)
    }
    screws = CornerPattern(screw, body, inset=10)
    Countersink(screw, diameter=9 mm)

    drawing label {
        t = Text("CHARGE", (0, 0), size=8)
    }
    AlignCenterX(label, body)
    label.t.position.y == body.bb.bottom + 20 mm

    assert body.bb.width == 200 mm and body.bb.height == 120 mm, "200 x 120 plate"
    assert len(cables) == 3, "three cable slots"
    assert cables[1].s.center.x - cables[0].s.center.x == 50 mm, "slots 50 apart"
    assert body.bb.top - cable.s.center.y == 35 mm, "slots 35 below the top"
    assert cable.s.width == 6 mm and cable.s.length == 20 mm, "6 x 20 slots"
    assert len(screws) == 4, "four screws"
    assert screw.c.center.x - body.bb.left == 10 mm, "screws 10 in"
}
