# Request (toys): a tabletop "sling puck" game (fast track), all in 6 mm birch ply.
# - Base board 500 x 260 mm, corners R20. Four 8 mm holes for the dowel pegs that hold the two
#   elastic bands: 40 mm in from each end wall's inner face and 10 mm in from each side
#   rail's inner face. "SLING" engraved filled in the left half, "PUCK" in the right half,
#   bold sans 30 mm, each centred in its half.
# - Two identical frame layers glued on the base (a rim 12 mm tall): the same 500 x 260 R20
#   outline, rails 15 mm wide all round, a centre wall 20 mm thick across the board with a
#   50 mm opening in its middle; the two playing fields' corners R8.
# - Ten pucks 40 mm across: five with a 16 mm filled dot engraved, five with a 24 mm ring.
# Assembled: frames stacked on the base, five pucks in each half.

thickness 6 mm
t = 6 mm

L = 500 mm
W = 260 mm
rail = 15 mm
wall = 20 mm
goal = 50 mm
puck_d = 40 mm
field_l = L / 2 - rail - wall / 2     # one field's length, end wall to centre wall
field_w = W - 2 * rail
peg_x = L / 2 - rail - 40 mm
peg_y = W / 2 - rail - 10 mm
px = [-1, 1, 1, -1]
py = [-1, -1, 1, 1]

def frame_layer() -> solid {
    outline = RoundedRectangle(center=(0, 0), width=L, height=W, corner_radius=20 mm)
    Fixed(outline)
    hole field {
        left = RoundedRectangle(corner=(-L / 2 + rail, -W / 2 + rail),
                                opposite=(-wall / 2, W / 2 - rail), corner_radius=8 mm)
        right = RoundedRectangle(corner=(wall / 2, -W / 2 + rail),
                                 opposite=(L / 2 - rail, W / 2 - rail), corner_radius=8 mm)
        gap = Rectangle(center=(0, 0), width=wall + 2 mm, height=goal)
    }
}

assembly sling_puck {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=L, height=W, corner_radius=20 mm)
        Fixed(board)
        hole pegs {
            for i in range(4) {
                c = Circle(center=(px[i] * peg_x, py[i] * peg_y), diameter=8 mm)
            }
        }
        drawing words {
            sling = Text("SLING", position=(-(wall / 2 + field_l / 2), 0), size=30,
                         font="sans:Bold", valign="middle", fill=true)
            puck = Text("PUCK", position=(wall / 2 + field_l / 2, 0), size=30,
                        font="sans:Bold", valign="middle", fill=true)
        }
    }

    lower = frame_layer()
    upper = frame_layer()

    for i in range(10) {
        solid puck {
            disc = Circle(center=(-L / 2 + puck_d / 2 + 50 mm * i, -W / 2 - 40 mm),
                          diameter=puck_d)
            drawing mark {
                if i < 5 {
                    dot = Circle(center=(-L / 2 + puck_d / 2 + 50 mm * i, -W / 2 - 40 mm),
                                 diameter=16 mm, fill=true)
                } else {
                    ring = Circle(center=(-L / 2 + puck_d / 2 + 50 mm * i, -W / 2 - 40 mm),
                                  diameter=24 mm)
                }
            }
        }
        # in 3D: five in each field, standing on the base
        Place(puck, position=((-1 if i < 5 else 1) * (wall / 2 + 60 mm) -
                              (-L / 2 + puck_d / 2 + 50 mm * i),
                              -90 mm + 45 mm * (i % 5) - (-W / 2 - 40 mm), t))
    }

    # flat on the sheet
    Above(lower, base, gap=10)
    AlignLeft(lower, base)
    Above(upper, lower, gap=10)
    AlignLeft(upper, lower)

    # in 3D
    Place(base, position=(0, 0, 0))
    Place(lower, position=(0, 0, t))
    Place(upper, position=(0, 0, 2 * t))

    # the request's numbers
    assert base.board.bb.width == 500 mm and base.board.bb.height == 260 mm, "base 500 x 260"
    assert lower.outline.bb.right - lower.field.right.bb.right == 15 mm, "end rails 15 mm"
    assert lower.outline.bb.top - lower.field.right.bb.top == 15 mm, "side rails 15 mm"
    assert lower.field.right.bb.left - lower.field.left.bb.right == 20 mm, "centre wall 20 mm"
    assert lower.field.gap.bb.height == 50 mm, "50 mm opening"
    assert lower.field.gap.bb.height - puck_d >= 8 mm, "a puck passes the opening easily"
    assert len(puck) == 10, "ten pucks"
    assert puck[0].disc.diameter == 40 mm, "pucks 40 mm"
    assert lower.field.right.bb.right - base.pegs.c[1].center.x == 40 mm,
        "pegs 40 mm in from the end wall"
    assert lower.field.right.bb.top - base.pegs.c[2].center.y == 10 mm,
        "pegs 10 mm in from the side rail"
    assert base.words.sling.bb.width <= field_l - 20 mm, "SLING fits its half"
    assert distance(base.words, base.pegs) >= 5 mm, "words clear of the pegs"
}
