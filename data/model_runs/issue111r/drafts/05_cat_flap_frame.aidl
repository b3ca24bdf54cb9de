# Pet door: a cat-flap frame from 6 mm plywood, 220 x 240 mm outside with 15 mm corner
# radii; a 160 x 175 mm opening with 20 mm corner radii, centred left-right, its
# bottom 25 mm above the frame's bottom (a thicker sill); four 5 mm screw holes 12 mm in
# from each corner, countersunk to 10 mm; a 10 mm paw print engraved above the opening
# (a 6 mm pad circle and four 3 mm toe circles on a 6 mm radius arc above it).
thickness 6 mm

param w = 220 mm, min = 180 mm, max = 300 mm
param h = 240 mm, min = 200 mm, max = 320 mm

solid frame {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=15)

    hole opening {
        o = RoundedRectangle(center=(0, 0), width=160, height=175, corner_radius=20)
    }
    AlignCenterX(opening, body)
    opening.bb.bottom == body.bb.bottom + 25 mm

    hole screw {
        c = Circle(center=(0, 0), diameter=5)
    }
    screws = CornerPattern(screw, body, inset=12)
    Countersink(screw, diameter=10 mm)

    drawing paw {
        pad = Circle(center=(0, 0), diameter=6)
        for i in range(4) {
            toe = Circle(center=(0, 0), diameter=3)
            Coincident(toe.center, polar(pad.center, 6, 45 deg + i * 30 deg))
        }
    }
    AlignCenterX(paw.pad, body)
    paw.pad.center.y == (opening.bb.top + body.bb.top) / 2 - 3 mm

    assert body.bb.width == 220 mm and body.bb.height == 240 mm, "220 x 240 frame"
    assert opening.o.width == 160 mm and opening.o.height == 175 mm, "160 x 175 opening"
    assert opening.bb.bottom - body.bb.bottom == 25 mm, "sill 25"
    assert len(screws) == 4, "four screws"
    assert screw.c.center.x - body.bb.left == 12 mm, "screws 12 in"
    assert screw.c.diameter == 5 mm, "5 mm screws"
}
