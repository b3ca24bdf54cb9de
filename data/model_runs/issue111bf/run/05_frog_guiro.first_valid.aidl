# Request (music): a frog guiro for the school percussion box, three 6 mm ply layers glued into one
# 18 mm thick frog seen from the side, plus a scraper stick. The frog: a round 110 mm body, a
# 60 mm head in front, a bulging eye on top of the head, a thigh and a front leg, sitting on a flat
# belly cut 45 mm below the body's centre. Along its back 16 ridge notches 3 mm wide and 4 mm deep
# spread over 100 deg of the body's round (all three layers, so the comb is 18 mm wide). The middle
# layer is hollow: a 64 mm sound chamber that opens through an 8 mm mouth slot at the front. The two
# outer layers are mirror images, each engraved on its outside with an eye (filled pupil) and a
# smiling mouth. A 5 mm cord hole through the thigh ties on the stick: 160 x 10 mm, round ends,
# a 5 mm cord hole at one end, "RIBBIT" engraved.

units mm
thickness 6 mm

ply = 6 mm
belly = 45 mm       # flat belly below the body's centre

def first_ridge(s) = 50 deg if s > 0 else 30 deg

def frog_layer(s=1, face=true, chamber=false) -> solid {
    body = Circle(center=(0, 0), radius=55)
    head = Circle(center=(58 * s, -5), radius=30)
    eye_bump = Circle(center=(50 * s, 22), radius=10)
    thigh = Ellipse(center=(-28 * s, -32), rx=36, ry=16, rotation=-15 * s)
    front_leg = Slot(start=(30 * s, -20), end=(45 * s, -44), width=12)
    hole flat { r = Rectangle(center=(0, -belly - 40), width=240, height=80) }
    hole ridge {
        n = Rectangle(center=polar((0, 0), 55, first_ridge(s)), width=3, height=8,
                      rotation=first_ridge(s) - 90 deg)
    }
    ridges = CircularPattern(ridge, 16, (0, 0), angle=100 deg)
    hole cord { c = Circle(center=(-40 * s, -30), diameter=5) }
    if chamber {
        hole sound {
            c = Circle(center=(0, -5), radius=32)
            port = Rectangle(center=(62 * s, -10), width=70, height=8)
        }
    }
    if face {
        drawing features {
            eye = Circle(center=(50 * s, 22), radius=6)
            pupil = Circle(center=(51 * s, 22), radius=3, fill=true)
            mouth = Arc(start=(86 * s, -8), through=(66 * s, -15), end=(44 * s, -10))
        }
    }
}

assembly guiro {
    outer_a = frog_layer(s=1, face=true)
    middle = frog_layer(s=1, face=false, chamber=true)
    outer_b = frog_layer(s=-1, face=true)

    solid stick {
        bar = RoundedRectangle(center=(0, 0), width=160, height=10, corner_radius=5)
        hole cord { c = Circle(center=(-73, 0), diameter=5) }
        drawing word { t = Text("RIBBIT", position=(10, 0), size=5, valign="middle") }
    }

    # 3D: the frog sits on its flat belly, layers stacked along y, engraved faces outward
    Place(outer_a, rotation=(90 deg, 0, 0), position=(0, ply, belly))
    Place(middle, rotation=(90 deg, 0, 0), position=(0, 2 * ply, belly))
    Place(outer_b, rotation=(90 deg, 0, 180 deg), position=(0, 2 * ply, belly))

    # flat on the sheet
    RightOf(middle, outer_a, gap=5)
    AlignBottom(middle, outer_a)
    RightOf(outer_b, middle, gap=5)
    AlignBottom(outer_b, middle)
    Below(stick, outer_a, gap=5)
    AlignLeft(stick, outer_a)

    assert len(outer_a.ridges) == 16, "16 ridges"
    assert outer_a.ridge.n.width == 3 mm, "ridge notches 3 mm wide"
    assert outer_a.body.radius * 2 == 110 mm and outer_a.head.radius * 2 == 60 mm, "110 mm body, 60 mm head"
    assert outer_a.body.center.y - outer_a.flat.r.bb.top == 45 mm, "flat belly 45 mm below the centre"
    assert middle.sound.c.radius * 2 == 64 mm and middle.sound.port.height == 8 mm, "64 mm chamber, 8 mm mouth"
    assert middle.sound.port.bb.right > middle.head.bb.right, "the mouth slot opens at the front"
    assert stick.bar.bb.width == 160 mm and stick.bar.bb.height == 10 mm, "stick 160 x 10"
}
