# Request: a "hook a fish" game for a children's party, 6 mm poplar ply.
# - A pond board, a wavy blob about 500 x 300, with six slots 22 x 7 (loose for small hands)
#   in two rows of three at 150 mm pitch (rows 100 mm apart), and "GONE FISHING" engraved
#   filled (bold, 18 mm) along the front.
# - Six fish, 125 mm nose to tail: an oval body 100 x 50, a triangular tail, a dorsal fin with
#   a 12 mm hole for the hook, an engraved eye and the fish's score 1-6 engraved filled
#   (bold, 16 mm) on the body; each stands in its slot on a 20 mm belly tab.

units mm
thickness 6 mm

T = 6 mm
SLOT_X = [-150, 0, 150, -150, 0, 150]
SLOT_Y = [-40, -40, -40, 60, 60, 60]
BODY_CY = T + 25 mm       # the body's centre: belly resting on the board

def fish(n=1) -> solid {
    body = Ellipse(center=(0, BODY_CY), rx=50, ry=25)
    tail = Polygon([(42, BODY_CY), (75, BODY_CY + 22), (75, BODY_CY - 22)])
    fin = Hull(Circle(center=(0, BODY_CY + 33), radius=12), Point(-28, BODY_CY + 15),
               Point(22, BODY_CY + 15))
    tab = Rectangle(center=(0, 5), width=20, height=10)    # tip on y = 0
    hole hook {
        c = Circle(center=(0, BODY_CY + 33), diameter=12)
    }
    drawing face {
        eye = Circle(center=(-32, BODY_CY + 7), radius=4)
        gill = Arc(center=(-40, BODY_CY), radius=18, start_angle=-40 deg, end_angle=40 deg)
        score = Text(str(n), position=(8, BODY_CY), size=16, font="sans:Bold",
                     valign="middle", fill=true)
    }
}

assembly game {
    solid pond {
        water = Spline([(-250, 0), (-210, 120), (-60, 150), (100, 140), (240, 110), (255, -30),
                        (160, -150), (-40, -140), (-200, -130)], closed=true)
        for i in range(6) {
            hole slot {
                s = Rectangle(center=(SLOT_X[i], SLOT_Y[i]), width=22, height=7)
            }
        }
        drawing title {
            t = Text("GONE FISHING", position=(0, -108), size=18, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    for i in range(6) {
        f = fish(n=i + 1)
        # on the sheet: two rows of three right of the pond
        f.bb.left == pond.bb.right + 10 + (i % 3) * 135
        f.bb.bottom == pond.bb.bottom + (i // 3) * 95
        # assembled: standing in its slot
        Place(f, rotation=(90 deg, 0, 0), position=(SLOT_X[i], SLOT_Y[i] + T / 2, 0))
    }

    # the request's numbers
    assert len(f) == 6, "six fish"
    assert f[0].bb.width == 125 mm, "fish 125 mm nose to tail"
    assert f[0].body.rx * 2 == 100 mm and f[0].body.ry * 2 == 50 mm, "body 100 x 50"
    assert f[0].hook.c.diameter == 12 mm, "12 mm hook hole"
    assert f[5].face.score.text == "6", "scores 1-6"
    assert pond.slot[0].s.width - f[0].tab.width == 2 mm, "slots loose on the tabs"
    assert pond.slot[1].s.center.x - pond.slot[0].s.center.x == 150 mm, "150 mm pitch"
    assert pond.slot[3].s.center.y - pond.slot[0].s.center.y == 100 mm, "rows 100 mm apart"
    assert f[0].body.bb.bottom - f[0].tab.bb.bottom == T, "belly rests on the board"
    assert pond.bb.width <= 520 mm and pond.bb.height <= 320 mm, "pond about 500 x 300"
}
