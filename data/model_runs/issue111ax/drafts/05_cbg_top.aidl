# Request (music): a new top for my 3-string cigar box guitar, 3 mm ply, 240 x 170 mm
# (square corners, like the box). Two f-holes, mirror images either side of the strings'
# centre line: each an S-shaped 5 mm band about 80 mm long with a 10 mm round eye at its
# tail end and an 8 mm eye at its head end, kept at least 5 mm clear of the 50 mm wide neck
# stick glued under the top along the centre line. An engraved bridge line 70 mm long
# across the strings, 65 mm from the tail edge (the right-hand short edge), labelled
# "BRIDGE" (4 mm, along the line). Four M3 countersunk screw holes (6 mm heads) 8 mm in
# from each corner. "Delta No. 1" engraved filled in a serif font, 8 mm tall, in the lower
# left, clear of the f-hole and the screws.
units mm
thickness 3 mm
import "std/fasteners.aidl"

param L = 240 mm, min = 200, max = 300
param W = 170 mm, min = 140, max = 220
NECK = 50 mm

solid top {
    body = Rectangle(center=(0, 0), width=L, height=W)
    axis = Line((-L / 2, 0), (L / 2, 0), construction=true)

    hole f_upper {
        tail_eye = Circle(center=(-48, 45), diameter=10)
        head_eye = Circle(center=(28, 55), diameter=8)
        band = Stroke(Spline([(-48, 45), (-28, 45), (-8, 54), (12, 57), (28, 55)]), width=5)
    }
    f_lower = Mirrored(f_upper, about=axis)

    screw = clearance_hole(size=3)
    screws = CornerPattern(screw, body, inset=8)
    Countersink(screws, diameter=6 mm)

    drawing bridge {
        line = Line((L / 2 - 65, -35), (L / 2 - 65, 35))
        label = Text("BRIDGE", position=(L / 2 - 65 + 6, 0), size=4, rotation=90 deg,
                     valign="middle")
    }

    drawing maker {
        t = Text("Delta No. 1", position=(-75, -68), size=8, font="serif", fill=true,
                 valign="middle")
    }

    assert body.bb.width == 240 mm and body.bb.height == 170 mm, "240 x 170 top"
    assert f_upper.tail_eye.diameter == 10 mm and f_upper.head_eye.diameter == 8 mm, "eyes"
    assert abs(distance(f_upper.tail_eye.center, f_upper.head_eye.center) - 80 mm) <= 5 mm,
        "f-holes about 80 mm long"
    assert f_upper.bb.bottom >= NECK / 2 + 5 mm, "upper f-hole 5 mm clear of the neck"
    assert f_lower.bb.top <= -(NECK / 2 + 5 mm), "lower f-hole 5 mm clear of the neck"
    assert bridge.line.length == 70 mm, "70 mm bridge line"
    assert body.bb.right - bridge.line.start.x == 65 mm, "bridge 65 mm from the tail edge"
    assert len(screws) == 4, "four screws"
    assert screws[0].c.center.x - body.bb.left == 8 mm, "screws 8 mm in"
    assert maker.bb.right < f_lower.bb.left - 3 mm or maker.bb.top < f_lower.bb.bottom - 3 mm,
        "label clear of the f-hole"
    assert maker.bb.left > screws[0].c.center.x + 6 mm, "label clear of the screw"
}
