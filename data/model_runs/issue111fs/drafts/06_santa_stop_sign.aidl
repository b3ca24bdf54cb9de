# Request (holidays): "A 'Santa please stop here' lawn sign for Christmas Eve, from 6 mm exterior
# ply. The board is 300 mm wide, its straight sides 300 mm tall, with an arched top rising to
# 360 mm in the middle. SANTA is stencil-cut right through (bold, 55 mm tall, at most 220 mm
# wide); PLEASE STOP and HERE are fill-engraved below it (bold, 28 mm tall, at most 220 wide); a
# five-pointed star (outer radius 28, inner 11) is cut out under the arch; a 6 mm border band is
# fill-engraved 18 mm in from the edge all round. A stake 60 mm wide, 450 mm long overall with a
# 60 mm point, slides onto the board's bottom edge with a flat sliding dovetail (2 tails, 15 mm
# deep, 10 degrees, 0.15 mm clearance in the sockets) so it comes off to store the sign flat.
# Everything at least 5 mm clear of everything else."

import "std/joints.aidl"

thickness 6 mm
W = 300 mm
shoulder = 300 mm
apex = 360 mm
# the arch's circle through both shoulders and the apex
R = ((W / 2) ** 2 + (apex - shoulder) ** 2) / (2 * (apex - shoulder))
cy_arch = apex - R
inset = 18 mm
band = 6 mm
stake_w = 60 mm
stake_l = 450 mm
point = 60 mm
dt_depth = 15 mm

assembly sign {
    solid board {
        shape = Intersect(Rectangle(bottom_left=(-W / 2, 0), width=W, height=apex),
                          Circle(center=(0, cy_arch), radius=R))
        sockets = dovetail(part="socket", length=stake_w, depth=dt_depth, tails=2, angle=10 deg,
                           clearance=0.15 mm, cx=0 mm, cy=0 mm)
        hole word {
            santa = Text("SANTA", position=(0, 215), size=55, font="sans:Bold", valign="middle",
                         stencil=true, max_width=220)
        }
        hole star_cut {
            s = Star(center=(0, 295), points=5, outer_radius=28, inner_radius=11)
        }
        drawing words {
            please = Text("PLEASE STOP", position=(0, 140), size=28, font="sans:Bold",
                          valign="middle", fill=true, max_width=220)
            here = Text("HERE", position=(0, 95), size=28, font="sans:Bold", valign="middle",
                        fill=true, max_width=220)
        }
        drawing border {
            edge = Intersect(Rectangle(bottom_left=(-W / 2 + inset, inset), width=W - 2 * inset,
                                       height=apex - 2 * inset),
                             Circle(center=(0, cy_arch), radius=R - inset), construction=true)
            b = Shell(edge, -band, fill=true)
        }
    }

    solid stake {
        body = Polygon([(-stake_w / 2, dt_depth), (stake_w / 2, dt_depth),
                        (stake_w / 2, dt_depth - stake_l + point), (0, dt_depth - stake_l),
                        (-stake_w / 2, dt_depth - stake_l + point)])
        tails = dovetail(part="tail", length=stake_w, depth=dt_depth, tails=2, angle=10 deg,
                         cx=0 mm, cy=0 mm)
    }

    RightOf(stake, board, gap=10)

    # 3D: the sign stands upright facing the street, the stake's tails in the board's sockets
    Place(board, position=(0, 0, 0), face="front", up="up")
    Place(stake, position=(0, 0, 0), face="front", up="up")

    # the request's numbers
    assert board.shape.bb.width == 300 mm, "300 wide"
    assert board.shape.bb.height == 360 mm, "arch rises to 360"
    assert sqrt(R ** 2 - (W / 2) ** 2) + cy_arch == 300 mm, "straight sides 300 tall"
    assert board.word.santa.size <= 55 mm and board.word.bb.width <= 220 mm, "SANTA 55 tall, at most 220 wide"
    assert board.words.bb.width <= 220 mm, "PLEASE STOP at most 220 wide"
    assert board.star_cut.s.outer_radius == 28 mm and board.star_cut.s.inner_radius == 11 mm, "star 28 / 11"
    assert stake.body.bb.width == 60 mm and stake.body.bb.height == 450 mm, "stake 60 x 450"
    assert stake.body.points[2][1] - stake.body.points[3][1] == 60 mm, "60 mm point"
    assert board.sockets.depth == 15 mm and board.sockets.tails == 2, "2 tails 15 deep"
    # clearances
    assert distance(board.word, board.star_cut) >= 5 mm, "SANTA clear of the star"
    assert distance(board.word, board.words) >= 5 mm, "SANTA clear of PLEASE STOP"
    assert distance(board.words.please, board.words.here) >= 5 mm, "lines apart"
    assert distance(board.star_cut, board.border) >= 5 mm, "star inside the border"
    assert distance(board.word, board.border) >= 5 mm, "SANTA inside the border"
    assert distance(board.words, board.border) >= 5 mm, "PLEASE STOP HERE inside the border"
    assert distance(board.sockets, board.border) >= 2 mm, "the border clears the sockets"
}
