# Request (pets): a dog ball thrower, two layers of 6 mm birch ply glued into one 12 mm
# launcher, 450 mm long overall. A 56 x 140 mm handle with rounded corners, a 100 x 26 mm
# hand hole in it and a 6 mm lanyard hole below the hand hole; a 32 mm wide arm bowing
# gently (18 mm off the straight line) up to a 90 mm round head with a 58 mm hole that holds a
# 65 mm tennis ball. The top layer has the dog's name "BISCUIT" engraved filled along the arm
# and a paw print engraved filled on the arm just above the handle.

units mm
thickness 6 mm

length = 450 mm
head_d = 90 mm
ball_hole = 58 mm
arm_w = 32 mm
bow = 18 mm

def layer(name="") -> solid {
    grip = RoundedRectangle(center=(0, 70), width=56, height=140, corner_radius=20)
    bend = Arc(start=(0, 130), through=(bow, 270), end=(0, length - head_d / 2))
    arm = Stroke(bend, arm_w)
    head = Circle(center=(0, length - head_d / 2), diameter=head_d)
    hole hand { s = Slot(center=(0, 72), length=100, width=26, rotation=90 deg) }
    hole lanyard { c = Circle(center=(0, 11), diameter=6) }
    hole ball { c = Circle(center=(0, length - head_d / 2), diameter=ball_hole) }

    if name != "" {
        drawing label {
            t = Text(name, position=(bow, 270), size=12, rotation=90 deg, font="sans:Bold",
                     valign="middle", fill=true)
        }
        Coincident(label.t.position, bend.through)

        drawing paw {
            pad = Ellipse(center=(8, 170), rx=6, ry=5, fill=true)
            for i in range(4) {
                toe = Circle(center=(8 + (i - 1.5) * 5, 180 + (3 if i == 1 or i == 2 else 0)),
                             radius=2.2, fill=true)
            }
        }
        Rigid(paw)
        OnCircle(paw.pad.center, bend)
        paw.pad.center.y == 170
    }
}

assembly thrower {
    top = layer(name="BISCUIT")
    bottom = layer()

    RightOf(bottom, top, gap=10)
    AlignBottom(bottom, top)

    # glued face to face: the bottom layer on the table, the engraved one on it
    Place(bottom, position=(0, 0, 0), face="up")
    Place(top, position=(0, 0, 6), face="up")

    # the request's numbers
    assert top.bb.height == 450 mm, "450 mm overall"
    assert top.head.diameter == 90 mm and top.ball.c.diameter == 58 mm, "head 90, ball hole 58"
    assert top.ball.c.diameter < 65 mm, "the tennis ball must not fall through"
    assert top.grip.bb.width == 56 mm and top.grip.bb.height == 140 mm, "handle 56 x 140"
    assert top.hand.s.length == 100 mm and top.hand.s.width == 26 mm, "hand hole 100 x 26"
    assert top.hand.s.bb.bottom - top.lanyard.c.center.y > 6 mm, "lanyard hole below the hand hole"
    assert len(top.paw.toe) == 4, "four toes"
}
