# Request: a hanging barber-shop sign in three glued layers. A backing of 6 mm ply (painted
# navy) 360 wide, 120 tall at its sides and 170 at the middle of an arched top (the arch part
# of a 350 mm radius circle), bottom corners R12, with two 6 mm holes 300 apart and 40 above
# the middle of the straight part for the hanging chains, "EST. 2024" and "HOT TOWEL SHAVES"
# engraved under the word. On the left, 135 from the middle: a barber pole from 3 mm white
# acrylic, 120 tall: a 28 x 80 tube with R3 corners, 20 mm balls top and bottom joined to it
# by collar bands 34 x 4, and four slanted stripes (9 tall, 20 mm pitch, rising 24 across)
# cut through it inside a 3 mm border so the navy shows. "BARBER" in 3 mm gold mirror
# acrylic, bold serif, 40 tall but at most 230 wide, standing on a 5 mm rail as one piece,
# its baseline 10 below the middle, centred in the space right of the pole.

import "std/fasteners.aidl"

thickness 6 mm

assembly sign {
    solid backing {
        body = Rectangle(center=(0, -20), width=360, height=120)
        cap = Intersect(Circle(center=(0, -260), radius=350),
                        Rectangle(center=(0, 40), width=360, height=100))
        Fillet([body.bottom_left, body.bottom_right], 12 mm)
        for s in [-1, 1] {
            hang = clearance_hole(size=6, cx=s * 150, cy=40)
        }
        drawing words {
            est = Text("EST. 2024", position=(32, -35), size=9, valign="middle")
            shaves = Text("HOT TOWEL SHAVES", position=(32, -58), size=7, valign="middle")
        }
    }

    solid pole {
        thickness 3 mm
        tube = RoundedRectangle(center=(0, 0), width=28, height=80, corner_radius=3)
        for s in [-1, 1] {
            collar = Rectangle(center=(0, s * 41), width=34, height=4)
            ball = Circle(center=(0, s * 50), radius=10)
        }
        hole stripes {
            for k in range(4) {
                st = Intersect(Rectangle(center=(0, 0), width=22, height=74),
                               Polygon([(-20, -48 + 20 * k), (20, -24 + 20 * k),
                                        (20, -15 + 20 * k), (-20, -39 + 20 * k)]))
            }
        }
    }

    solid letters {
        thickness 3 mm
        word = Text("BARBER", position=(32, -10), size=40, font="serif:Bold", max_width=230)
        rail = Rectangle(center=(word.bb.center_x, -12.5), width=word.bb.width, height=5)
    }

    Below(pole, backing, gap=10)
    AlignLeft(pole, backing)
    RightOf(letters, pole, gap=10)
    AlignTop(letters, pole)

    Place(backing, position=(0, 0, 0), face="front", up="up")
    Place(pole, on=backing, position=(-135, -10), face="up")
    Place(letters, on=backing, position=(0, 0), face="up")

    assert backing.body.bb.width == 360 mm, "360 wide"
    assert backing.cap.bb.top - backing.body.bb.bottom == 170 mm, "170 at the middle"
    assert backing.hang[1].c.center.x - backing.hang[0].c.center.x == 300 mm, "holes 300 apart"
    assert pole.bb.height == 120 mm, "pole 120 tall"
    assert letters.word.bb.width <= 230 mm, "word at most 230 wide"
    assert letters.rail.bb.height == 5 mm, "5 mm rail"
}
