# Request (holidays): a "Christmas Eve" board for Santa's milk and cookies, two layers of
# 3 mm ply glued together, each 320 x 220 mm with 12 mm rounded corners. The top layer is
# pierced with recesses: a 75 mm circle for the milk glass (left), a 100 mm circle for the
# cookies (right of it) and a carrot 150 mm long, 28 mm wide at its top and 6 mm at its tip,
# lying along the bottom. Engraved on the top layer: "CHRISTMAS EVE" as filled bold serif
# letters 14 mm tall across the top, between two filled 5-pointed stars 16 mm across;
# "MILK" and "COOKIES" 7 mm tall under their recesses, "FOR RUDOLPH" 7 mm tall under the
# carrot, and three carrot-top leaves as engraved lines at the carrot's wide end.

thickness 3 mm

W = 320 mm
H = 220 mm
R = 12 mm
GLASS = (-105, 25)
COOKIE = (30, 25)
CARROT_Y = -58 mm

assembly christmas_eve_board {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=R)
    }

    solid top {
        board = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=R)
        hole glass {
            c = Circle(center=GLASS, diameter=75)
        }
        hole cookies {
            c = Circle(center=COOKIE, diameter=100)
        }
        hole carrot {
            thick = Circle(center=(-61, CARROT_Y), radius=14)
            tip = Circle(center=(72, CARROT_Y), radius=3)
            shape = Hull(thick, tip)
        }
        drawing words {
            title = Text("CHRISTMAS EVE", position=(0, 92), size=14, font="serif:Bold",
                         valign="middle", fill=true)
            star_l = Star(center=(-118, 92), points=5, outer_radius=8, inner_radius=3.5,
                          fill=true)
            star_r = Star(center=(118, 92), points=5, outer_radius=8, inner_radius=3.5,
                          fill=true)
            milk = Text("MILK", position=(GLASS[0], -24), size=7, valign="middle")
            cookie = Text("COOKIES", position=(COOKIE[0], -36), size=7, valign="middle")
            rudolph = Text("FOR RUDOLPH", position=(0, -88), size=7, valign="middle")
            # FIX after the first valid program: W0516 x 3, the leaves began on the carrot's cut
            # edge; they now start 0.6 mm clear of it, as the hint says (the look is the same)
            leaf1 = Line((-75.6, CARROT_Y), (-95, CARROT_Y + 12))
            leaf2 = Line((-75.6, CARROT_Y), (-98, CARROT_Y))
            leaf3 = Line((-75.6, CARROT_Y), (-95, CARROT_Y - 12))
        }
    }

    # on the sheet: top layer to the right of the base
    RightOf(top, base, gap=10)
    AlignBottom(top, base)

    # in 3D: the top layer glued on the base
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, 3))

    # the request's numbers
    assert base.board.width == 320 mm and base.board.height == 220 mm, "320 x 220"
    assert top.glass.c.diameter == 75 mm, "75 mm glass"
    assert top.cookies.c.diameter == 100 mm, "100 mm cookies"
    assert top.carrot.tip.center.x + 3 mm - (top.carrot.thick.center.x - 14 mm) == 150 mm,
        "carrot 150 long"
    assert top.carrot.thick.radius * 2 == 28 mm and top.carrot.tip.radius * 2 == 6 mm,
        "carrot 28 to 6 wide"
    assert top.glass.bb.right < top.cookies.bb.left, "glass left of the cookies"
    assert top.words.title.bb.left > top.words.star_l.bb.right, "title clear of the left star"
    assert top.words.title.bb.right < top.words.star_r.bb.left, "title clear of the right star"
}
