# Request (signs): a garden-railway crossbuck sign in 6 mm exterior ply, painted white with
# engraved, filled black letters.
# - The X is one piece: two 450 x 80 mm boards crossing at right angles, each at 45 degrees,
#   every corner (outer and inner) rounded 6 mm. "RAIL" / "ROAD" on the board that runs
#   from upper left to lower right, "CROSS" / "ING" on the other, one word each side of the
#   crossing, bold letters 40 mm tall (at most 160 mm wide), reading along the boards.
#   Two 5.5 mm holes 40 mm apart, one above the other, at the crossing, countersunk 10 mm.
# - A 60 mm wide post, 450 mm long, pointed (60 mm long point) to push into the lawn, with
#   two 5.5 mm holes for the X (its centre 400 mm up) and two for the plate below.
# - A "2 TRACKS" plate 220 x 70 mm (letters 25 mm tall), 6 mm corners, two countersunk
#   5.5 mm holes 50 mm apart on its centre line, screwed to the post 260 mm up.
# FIX after the first valid program: W0517 was right: at 260 mm up the plate (225..295)
# overlapped the X's lower arms (its tips reach down to 212.6 mm). The plate goes to 160 mm
# up (125..195), under the X, as on a real crossbuck.

units mm
thickness 6 mm

ARM = 450 mm
BOARD = 80 mm
SIZE = 40 mm
WORD_AT = (ARM / 2 + BOARD / 2) / 2     # a word's centre from the crossing
X_UP = 400 mm
PLATE_UP = 160 mm

assembly crossbuck {
    solid x_sign {
        a = Rectangle(center=(0, 0), width=ARM, height=BOARD, rotation=-45 deg)
        b = Rectangle(center=(0, 0), width=ARM, height=BOARD, rotation=45 deg)
        hole screws {
            up = Circle(center=(0, 20), diameter=5.5)
            dn = Circle(center=(0, -20), diameter=5.5)
        }
        Countersink(screws, diameter=10 mm)
        drawing words {
            rail = Text("RAIL", position=(-WORD_AT * cos(45 deg), WORD_AT * sin(45 deg)), size=SIZE,
                        rotation=-45 deg, valign="middle", font="sans:Bold", fill=true, max_width=160)
            road = Text("ROAD", position=(WORD_AT * cos(45 deg), -WORD_AT * sin(45 deg)), size=SIZE,
                        rotation=-45 deg, valign="middle", font="sans:Bold", fill=true, max_width=160)
            cross = Text("CROSS", position=(-WORD_AT * cos(45 deg), -WORD_AT * sin(45 deg)),
                         size=SIZE, rotation=45 deg, valign="middle", font="sans:Bold", fill=true,
                         max_width=160)
            ing = Text("ING", position=(WORD_AT * cos(45 deg), WORD_AT * sin(45 deg)), size=SIZE,
                       rotation=45 deg, valign="middle", font="sans:Bold", fill=true, max_width=160)
        }
        Fillet(6)
        Fixed(a)
    }

    solid post {
        body = Polygon([(0, 0), (30, 60), (30, 450), (-30, 450), (-30, 60)])
        hole for_x {
            up = Circle(center=(0, X_UP + 20), diameter=5.5)
            dn = Circle(center=(0, X_UP - 20), diameter=5.5)
        }
        hole for_plate {
            up = Circle(center=(0, PLATE_UP + 25), diameter=5.5)
            dn = Circle(center=(0, PLATE_UP - 25), diameter=5.5)
        }
        Rigid(self)
    }

    solid plate {
        body = RoundedRectangle(center=(0, 0), width=220, height=70, corner_radius=6)
        hole screws {
            up = Circle(center=(0, 25), diameter=5.5)
            dn = Circle(center=(0, -25), diameter=5.5)
        }
        Countersink(screws, diameter=10 mm)
        drawing words {
            t = Text("2 TRACKS", position=(0, 0), size=25, valign="middle", font="sans:Bold",
                     fill=true)
        }
        Rigid(self)
    }

    # flat layout
    RightOf(post, x_sign, gap=6)
    AlignBottom(post, x_sign)
    RightOf(plate, post, gap=6)
    AlignTop(plate, post)

    # 3D: the post's front face at y = 0, the X and the plate screwed on in front of it
    Place(post, position=(0, 6, 0), face="front", up="up")
    Place(x_sign, position=(0, 0, X_UP), face="front", up="up")
    Place(plate, position=(0, 0, PLATE_UP), face="front", up="up")

    # the request's numbers
    assert x_sign.a.width == 450 mm and x_sign.a.height == 80 mm, "boards 450 x 80"
    assert abs(x_sign.bb.width - (450 mm + 80 mm) / sqrt(2)) < 0.01 mm, "X at right angles"
    assert x_sign.screws.up.center.y - x_sign.screws.dn.center.y == 40 mm, "X screws 40 apart"
    assert x_sign.words.rail.size <= 40 mm, "letters 40 tall at most"
    assert post.body.bb.height == 450 mm and post.body.bb.width == 60 mm, "post 60 x 450"
    assert post.for_x.up.center.y - X_UP == 20 mm, "X centred 400 up"
    assert plate.body.width == 220 mm and plate.body.height == 70 mm, "plate 220 x 70"
    assert plate.screws.up.center.y - plate.screws.dn.center.y == 50 mm, "plate screws 50 apart"
    assert distance(x_sign.words, x_sign.screws) >= 3 mm, "letters clear of the screws"
    assert distance(plate.words, plate.screws) >= 3 mm, "letters clear of the screws"
}
