# Request (sport): wooden pickleball paddles for our school club, 8 mm birch ply.
# The paddle is 400 mm long and 195 mm wide (legal: length + width at most 24 in, length
# at most 17 in): a 130 mm handle 32 mm wide flaring through a smooth throat into a head
# with straight sides 195 mm apart from 200 to 330 mm up and a round top. Two handle
# scales 32 x 130 mm are glued on either side to thicken the grip; three 5 mm rivet holes
# through the handle and both scales, 25, 65 and 105 mm from the butt. "RIVERSIDE" over
# "PICKLEBALL" engraved filled in bold letters 14 mm high on the head, centred at 290 and
# 265 mm up.

units mm
thickness 8 mm

half = [(0, 0), (16, 0), (16, 130), (30, 148), (70, 165), (97.5, 200), (97.5, 330),
        (85, 375), (50, 397), (0, 400)]
rivets = [25 mm, 65 mm, 105 mm]

def scale() -> solid {
    grip = Rectangle(bottom_left=(-16, 0), width=32, height=130)
    hole pins {
        for i in range(3) {
            c = Circle(center=(0, rivets[i]), diameter=5)
        }
    }
    assert grip.width == 32 mm and grip.height == 130 mm, "scale 32 x 130"
}

assembly paddle {
    solid core {
        outline = Spline(half, closed=true, mirror="y", corners=[1, 2, 16, 17])
        hole pins {
            for i in range(3) {
                c = Circle(center=(0, rivets[i]), diameter=5)
            }
        }
        drawing name {
            a = Text("RIVERSIDE", position=(0, 290), size=14, font="sans:Bold",
                     valign="middle", fill=true)
            b = Text("PICKLEBALL", position=(0, 265), size=14, font="sans:Bold",
                     valign="middle", fill=true)
        }
        Fixed(outline)
        assert outline.points[9].y - outline.points[0].y == 400 mm, "400 mm long"
        assert outline.points[5].x * 2 == 195 mm and outline.points[6].x * 2 == 195 mm,
            "195 mm wide"
        assert outline.points[2].y - outline.points[1].y == 130 mm, "130 mm handle"
        assert outline.points[1].x * 2 == 32 mm, "32 mm handle"
        assert outline.bb.width + outline.bb.height <= 24 in, "legal: length + width"
        assert outline.bb.height <= 17 in, "legal: length"
        assert pins.c[0].center.y == 25 mm and pins.c[2].center.y == 105 mm, "rivets 25..105"
    }

    scale_a = scale()
    scale_b = scale()

    RightOf(scale_a, core, gap=10 mm)
    AlignBottom(scale_a, core)
    RightOf(scale_b, scale_a, gap=10 mm)
    AlignBottom(scale_b, core)
}
