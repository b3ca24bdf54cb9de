# Egg tray top plate (kitchen): 180 x 125 mm plate, R6 corners, 3 mm plywood; six 42 mm egg
# holes in 2 rows x 3 columns at 55 mm pitch, the grid centered on the plate; four 3.5 mm screw
# holes 7 mm in from each corner (for M3 standoffs to the bottom plate), countersunk 7 mm;
# "FRESH EGGS" engraved 6 mm tall, centered in the top margin above the egg holes.

thickness 3 mm

param egg_d = 42 mm, min = 35 mm, max = 48 mm
param pitch = 55 mm, min = 50 mm, max = 60 mm

solid tray {
    body = RoundedRectangle(center=(0, 0), width=180, height=125, corner_radius=6)
    Fixed(body)

    hole egg {
        c = Circle(center=(-pitch, -pitch / 2), diameter=egg_d)
    }
    eggs = GridPattern(egg, 2, 3, pitch)

    hole screw {
        c = Circle(center=(-83, -55.5), diameter=3.5)
    }
    screws = CornerPattern(screw, body, inset=7)
    Countersink(screws, diameter=7)

    drawing label {
        word = Text("FRESH EGGS", (0, 0), size=6, valign="middle")
    }
    AlignCenterX(label, body)
    # centered in the top margin between the upper egg row and the plate's edge
    label.bb.center_y == (eggs[5].bb.top + body.bb.top) / 2

    assert body.bb.width == 180 mm, "180 mm wide"
    assert body.bb.height == 125 mm, "125 mm tall"
    assert len(eggs) == 6, "six egg holes"
    assert egg.c.diameter == 42 mm, "42 mm egg holes"
    assert eggs[1].c.center.x - eggs[0].c.center.x == 55 mm, "55 mm pitch"
    assert abs((eggs[0].bb.left - body.bb.left) - (body.bb.right - eggs[5].bb.right)) < 0.01 mm, "grid centered in x"
    assert abs((eggs[0].bb.bottom - body.bb.bottom) - (body.bb.top - eggs[5].bb.top)) < 0.01 mm, "grid centered in y"
    assert screws[0].c.center.x - body.bb.left == 7 mm, "screws 7 mm in"
    assert len(screws) == 4, "four screw holes"
    assert label.word.size == 6 mm, "6 mm text"
}
