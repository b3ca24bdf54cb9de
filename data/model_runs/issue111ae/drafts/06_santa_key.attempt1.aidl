# Request (holidays): a "Santa's magic key" to hang on the front door on Christmas Eve, for
# homes without a chimney, 3 mm birch ply, with a gift tag.
# - Key: a round bow 60 mm across with 8 scallops (R6 discs centred on its rim, the first at
#   22.5 deg so none sits where the shaft leaves), a five-pointed star window 32 mm tip to
#   tip (inner radius 7) in the bow's centre, a 5 mm hanging hole 23 mm above the bow's
#   centre, "NORTH POLE" engraved 4.5 mm high round the bottom of the bow, reading upright.
#   A 12 mm shaft to a 14 mm ball whose centre is 150 mm from the bow's centre, a 6 x 22 mm
#   R2 collar 42 mm from the bow's centre, a 22 x 20 mm bit under the shaft 8 mm before the
#   ball's centre with a 6 mm ward notch 9 mm deep from its bottom edge, and "SANTA'S MAGIC
#   KEY" engraved along the shaft in bold serif, filled, at most 68 mm long.
# - Tag: 70 x 36 mm, pointed at the left end (the point 12 mm deep), corners R3, a 5 mm hole
#   9 mm from the point, "PLEASE LET" / "SANTA IN" engraved 6 mm high on two lines.

units mm
thickness 3 mm

param bow_d = 60 mm, min = 50 mm, max = 80 mm
param reach = 150 mm, min = 120 mm, max = 200 mm   # bow centre to ball centre

assembly santa_key {
    solid key {
        bow = Circle(center=(0, 0), diameter=bow_d)
        solid lobe { c = Circle(center=polar((0, 0), bow_d / 2, 22.5 deg), radius=6) }
        lobes = CircularPattern(lobe, 8, bow.center)
        shaft = Rectangle(bottom_left=(bow_d / 2 - 5, -6), width=reach - bow_d / 2 + 5,
                          height=12)
        collar = RoundedRectangle(center=(42, 0), width=6, height=22, corner_radius=2)
        ball = Circle(center=(reach, 0), diameter=14)
        bit = Rectangle(bottom_left=(reach - 8 - 22, -26), width=22, height=20)

        hole star_window {
            s = Star(center=(0, 0), points=5, outer_radius=16, inner_radius=7)
        }
        hole hang { c = Circle(center=(0, 23), diameter=5) }
        hole ward { n = Rectangle(center=(reach - 8 - 11, -21.5), width=6, height=9 + 1) }

        drawing words {
            t = Text("SANTA'S MAGIC KEY", position=((42 + 3 + reach - 7) / 2, 0), size=6,
                     font="serif:Bold", valign="middle", fill=true, max_width=68)
        }
        drawing pole {
            ring = Circle(center=(0, 0), radius=24, construction=true)
            t = Text("NORTH POLE", along=ring, size=4.5, flip=true)
        }
    }

    solid tag {
        body = Polygon([(12, 0), (70, 0), (70, 36), (12, 36), (0, 18)])
        Fillet(body, 3)
        hole eye { c = Circle(center=(9, 18), diameter=5) }
        drawing msg {
            a = Text("PLEASE LET", position=(41, 21), size=6)
            b = Text("SANTA IN", position=(41, 9), size=6)
        }
    }
    Fixed(key)
    Below(tag, key, gap=10)
    AlignLeft(tag, key)

    # the request's numbers
    assert key.bow.diameter == 60 mm, "bow 60 mm"
    assert len(key.lobes) == 8, "8 scallops"
    assert key.star_window.s.outer_radius * 2 == 32 mm, "star 32 tip to tip"
    assert key.hang.c.center.y - key.bow.center.y == 23 mm, "hanging hole 23 mm up"
    assert key.ball.center.x - key.bow.center.x == 150 mm, "ball 150 mm from the bow"
    assert key.ball.center.x - key.bit.bb.right == 8 mm, "bit 8 mm before the ball"
    assert key.bit.bb.top - key.ward.n.bb.top == 20 mm - 9 mm, "ward 9 mm deep"
    assert key.words.t.bb.width <= 68 mm, "words at most 68 long"
    assert key.words.t.bb.left > key.collar.bb.right + 2 mm, "words clear the collar"
    assert key.words.t.bb.right < key.bit.bb.right, "words end over the bit"
    assert tag.body.bb.width == 70 mm and tag.body.bb.height == 36 mm, "tag 70 x 36"
    assert tag.eye.c.center.x - tag.body.points[4].x == 9 mm, "tag hole 9 mm from the point"
}
