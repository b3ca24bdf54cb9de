# Request: a wedge volume for my home climbing wall, cut on my CNC router from 15 mm ply,
# glued and screwed. Outside: 400 wide along the wall, 300 tall, projecting 150 at the
# bottom and 0 at the top (a leaning face). Two right-triangle sides (legs 150 and 300) on
# the outside; between them a bottom 370 x 142.5 and a back 370 wide standing on the bottom
# against the wall up to where it meets the face (z 15 to 270); the face 400 wide rests on
# the sides' sloping edges. Face: six 12 mm holes for hold T-nuts in two rows of three
# (120 apart, 70 and 260 up the face from its bottom edge) and a 40 mm access hole for the
# socket, straight in front of the mounting bolt. Back: an 11 mm hole for the M10 mounting
# bolt 140 above the floor of the volume, centred, and two 5 mm anti-spin screw holes
# 120 either side of it. "WEDGE 400" engraved on the left side.

thickness 15 mm

W = 400 mm
H = 300 mm
D = 150 mm
T = 15 mm
SLOPE = sqrt(D ** 2 + H ** 2)
# the face's underside runs from (y -D, z 0) to (y 0, z H): y = -D (1 - z / H)
BACK_TOP = H * (1 - T / D)
BOLT_Z = 140 mm
# the point of the face's underside straight in front of the bolt, measured up the slope
ACCESS_S = (BOLT_Z / H) * SLOPE

assembly volume {
    solid side_l {
        tri = Polygon([(0, 0), (150, 0), (0, 300)])
        drawing mark {
            # FIX after the first valid program: centred where the triangle is 120 wide
            # (the text is anchored at its middle: at x 35 it ran off the left edge, W0505)
            t = Text("WEDGE 400", position=(58, 60), size=10, valign="middle")
        }
    }
    solid side_r {
        tri = Polygon([(0, 0), (-150, 0), (0, 300)])
    }
    solid bottom {
        board = Rectangle(bottom_left=(-W / 2 + T, -(D - D * T / H)), width=W - 2 * T,
                          height=D - D * T / H)
    }
    solid back {
        board = Rectangle(bottom_left=(-W / 2 + T, T), width=W - 2 * T, height=BACK_TOP - T)
        hole bolt { c = Circle(center=(0, BOLT_Z), diameter=11) }
        hole anti_spin {
            l = Circle(center=(-120, BOLT_Z), diameter=5)
            r = Circle(center=(120, BOLT_Z), diameter=5)
        }
    }
    solid face {
        board = Rectangle(bottom_left=(-W / 2, 0), width=W, height=SLOPE)
        hole tnuts {
            for row in [70, 260] {
                for col in [-120, 0, 120] {
                    c = Circle(center=(col, row), diameter=12)
                }
            }
        }
        hole access { c = Circle(center=(0, ACCESS_S), diameter=40) }
    }

    # flat on the sheet
    RightOf(side_r, side_l, gap=10)
    AlignBottom(side_r, side_l)
    RightOf(back, side_r, gap=10)
    AlignBottom(back, side_r)
    Above(bottom, back, gap=10)
    AlignLeft(bottom, back)
    RightOf(face, back, gap=10)
    AlignBottom(face, back)

    # in 3D: the wall is the plane y = 0, the volume stands out toward -y, z up
    Place(side_l, position=(-W / 2 + T, 0, 0), face="left", up="up")
    Place(side_r, position=(W / 2 - T, 0, 0), face="right", up="up")
    Place(bottom, position=(0, 0, 0), face="up", up="back")
    Place(back, position=(0, 0, 0), face="front", up="up")
    # FIX after the first valid program: the face leans back (a slab), its outward normal is
    # (0, -2, 1), square to the slope (0, 1, 2); (0, -2, -1) was not, and no message said so
    Place(face, position=(0, -D, 0), face=(0, -2, 1), up=(0, 1, 2))

    # the request's numbers
    assert side_l.tri.bb.width == 150 mm and side_l.tri.bb.height == 300 mm, "legs 150 and 300"
    assert face.board.width == 400 mm, "face 400 wide"
    assert abs(face.board.height - sqrt((150 mm) ** 2 + (300 mm) ** 2)) < 0.01 mm, "face spans the slope"
    assert bottom.board.width == 370 mm and abs(bottom.board.height - 142.5 mm) < 0.001 mm,
        "bottom 370 x 142.5"
    assert abs(back.board.bb.top - 270 mm) < 0.001 mm and back.board.bb.bottom == 15 mm, "back z 15 to 270"
    assert back.bolt.c.center.y == 140 mm, "bolt 140 up"
    assert back.anti_spin.r.center.x - back.bolt.c.center.x == 120 mm, "anti-spin 120 aside"
    assert face.tnuts.c[1][0].center.y - face.tnuts.c[0][0].center.y == 260 mm - 70 mm, "rows"
    assert face.tnuts.c[0][1].center.x - face.tnuts.c[0][0].center.x == 120 mm, "cols 120 apart"
    assert distance(face.access, face.tnuts) >= 20 mm, "access hole clear of the T-nuts"
}
