# Request (kitchen): a teapot-shaped rest for used teabags, two layers of 3 mm birch glued
# together. The teapot: a 90 x 70 mm oval body, a 50 x 6 mm lid band on top with a 10 mm round
# knob, a tapered spout rising to the right to about 74 mm from the centre, and a handle on the
# left (32 x 44 mm oval) with a 16 x 26 mm finger opening. Base layer: the whole teapot with
# "TEA" engraved filled, 14 mm sans bold capitals, in the middle of the body. Rim layer: the
# same teapot with the body hollowed out to leave a 6 mm wall, so drips stay in the well.

thickness 3 mm

param wall = 6 mm, min = 4 mm, max = 10 mm

def teapot() -> solid {
    body = Ellipse(center=(0, 0), rx=45, ry=35)
    lid = RoundedRectangle(center=(0, 36), width=50, height=6, corner_radius=2)
    knob = Circle(center=(0, 43), radius=5)
    spout = Polygon([(38, -16), (42, 10), (68, 30), (74, 28)])
    grip = Ellipse(center=(-56, 5), rx=16, ry=22)
    hole finger { e = Ellipse(center=(-56, 5), rx=8, ry=13) }
}

assembly teabag_rest {
    base = teapot()
    rim = teapot()

    drawing label {
        word = Text("TEA", position=(0, -2), size=14, font="sans:Bold", valign="middle",
                    fill=true)
    }
    CenterInside(label, base.body)
    CutInto(label, base)

    hole well { e = Ellipse(center=(0, 0), rx=45 - wall, ry=35 - wall) }
    Concentric(well.e, rim.body)
    CutInto(well, rim)

    RightOf(rim, base, gap=5)
    AlignCenterY(rim, base)

    Place(base, position=(0, 0, 0), face="up")
    Place(rim, position=(0, 0, 3), face="up")

    assert base.body.bb.width == 90 mm and base.body.bb.height == 70 mm
    assert base.lid.bb.width == 50 mm and base.knob.bb.width == 10 mm
    assert base.grip.bb.width == 32 mm and base.grip.bb.height == 44 mm
    assert base.finger.e.bb.width == 16 mm and base.finger.e.bb.height == 26 mm
    assert label.word.size == 14 mm
    assert rim.body.bb.width - well.e.bb.width == 2 * 6 mm, "6 mm wall"
    assert rim.body.bb.height - well.e.bb.height == 2 * 6 mm, "6 mm wall"
    assert base.spout.bb.right - base.body.center.x >= 72 mm
}
