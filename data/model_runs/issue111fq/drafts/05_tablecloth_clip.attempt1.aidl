# Request: four tablecloth clips for a garden party, so the wind cannot lift the cloth, cut
# from 6 mm clear acrylic. Each clip is a C that slides over the 25 mm table top from the
# side: arms 35 mm long and 8 mm thick, a spine 8 mm thick, an opening of 27 mm between the
# arms, narrowed to 25 mm by a 1 mm nub near each arm's tip (centre 4 mm from the tip). Under
# the spine hangs a party charm as a weight, on a neck 5 mm wide: a star (5 points, 30 mm
# tip to tip), a heart 34 mm wide, a balloon 22 x 28 mm with its knot, and a flower of five
# 14 mm petals round a centre with a 6 mm hole. Every corner rounded 1 mm (no sharp acrylic
# points at a party).

units mm
thickness 6 mm

OPEN = 27 mm
BAND = 8 mm
ARM = 35 mm
NUB = 1 mm
CY = -48 mm    # the charm's centre, below the spine

def clip(motif="star") -> solid {
    spine = Rectangle(bottom_left=(0, -OPEN / 2 - BAND), width=BAND, height=OPEN + 2 * BAND)
    top_arm = Rectangle(bottom_left=(0, OPEN / 2), width=ARM, height=BAND)
    bottom_arm = Rectangle(bottom_left=(0, -OPEN / 2 - BAND), width=ARM, height=BAND)
    top_nub = Circle(center=(ARM - 4, OPEN / 2 + 1.5 - NUB), radius=1.5)
    bottom_nub = Circle(center=(ARM - 4, -OPEN / 2 - 1.5 + NUB), radius=1.5)
    neck = Rectangle(bottom_left=(BAND / 2 - 2.5, -38), width=5, height=38 - OPEN / 2 - BAND + 1)
    solid charm {
        if motif == "star" {
            s = Star(center=(BAND / 2, CY), points=5, outer_radius=15, inner_radius=7)
        } elif motif == "heart" {
            lobe_l = Hull(Circle(center=(BAND / 2 - 8, CY + 5), radius=9), Point(BAND / 2, CY - 16))
            lobe_r = Hull(Circle(center=(BAND / 2 + 8, CY + 5), radius=9), Point(BAND / 2, CY - 16))
            Rigid(self)
        } elif motif == "balloon" {
            b = Ellipse(center=(BAND / 2, CY), rx=11, ry=14)
            knot = Triangle(center=(BAND / 2, CY - 14 - 0.5), base=6, height=5)
        } else {
            for i in range(5) {
                petal = Circle(center=(BAND / 2 + 8 * cos(90 deg + i * 72 deg),
                                       CY + 8 * sin(90 deg + i * 72 deg)), radius=7)
            }
            middle = Circle(center=(BAND / 2, CY), radius=6)
            hole eye { c = Circle(center=(BAND / 2, CY), diameter=6) }
        }
    }
    Fillet(1 mm)
}

assembly clips {
    star = clip(motif="star")
    heart = clip(motif="heart")
    balloon = clip(motif="balloon")
    flower = clip(motif="flower")
    RightOf(heart, star, gap=8 mm)
    AlignTop(heart, star)
    RightOf(balloon, heart, gap=8 mm)
    AlignTop(balloon, heart)
    RightOf(flower, balloon, gap=8 mm)
    AlignTop(flower, balloon)

    assert star.top_arm.bb.bottom - star.bottom_arm.bb.top == 27 mm, "27 mm opening"
    assert star.top_nub.bb.bottom - star.bottom_nub.bb.top == 25 mm, "25 mm at the nubs"
    assert star.top_arm.bb.width == 35 mm and star.top_arm.bb.height == 8 mm, "arms 35 x 8"
    assert star.spine.bb.width == 8 mm, "spine 8 thick"
    assert star.top_arm.bb.right - star.top_nub.center.x == 4 mm, "nub 4 mm from the tip"
    assert star.neck.bb.width == 5 mm, "neck 5 wide"
    assert star.charm.bb.height > 28 mm and star.charm.bb.height < 30 mm, "star 30 tip to tip"
    assert abs(heart.charm.bb.width - 34 mm) < 0.01 mm, "heart 34 wide"
    assert balloon.charm.b.bb.width == 22 mm and balloon.charm.b.bb.height == 28 mm,
        "balloon 22 x 28"
    assert flower.charm.petal[0].diameter == 14 mm, "14 mm petals"
    assert flower.charm.eye.c.diameter == 6 mm, "6 mm hole"
}
