# Request: "A quarter-scale tabletop cornhole board in 6 mm ply: a 150 x 300 mm deck with a
# 38 mm hole centred 57 mm below its top (back) edge, sloping from 20 mm above the table at
# the front to 80 mm at the back. Under it two side rails, 3 mm in from the deck's edges,
# whose top edges carry three 20 mm glued tabs each up through slots in the deck (flush
# with its face), and a 65 mm tall back board 10 mm in from the back, tabbed into both rails
# (two 15 mm tabs a side). Engrave 'CORNHOLE' in bold filled letters 14 mm tall, 60 mm above
# the deck's front edge, and a ring 6 mm outside the hole."

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
deck_w = 150 mm
deck_l = 300 mm
front_h = 20 mm
back_h = 80 mm
rise = back_h - front_h
run = sqrt(deck_l ** 2 - rise ** 2)
slope = asin(rise / deck_l)
rail_x = deck_w / 2 - 3 mm - t / 2     # a rail's middle, from the deck's centre line
back_board_h = 65 mm

def rail() -> solid {
    side = Polygon([(0, 0), (run, 0), (run, back_h), (0, front_h)])
    top_tabs = tab_and_slot(part="tab", length=deck_l, thickness=t, tabs=3, tab=20 mm,
                            screw=0, rotation=slope, cx=run / 2, cy=(front_h + back_h) / 2)
    back_slots = tab_and_slot(part="slot", length=back_board_h, thickness=t, tabs=2,
                              tab=15 mm, screw=0, rotation=90 deg, cx=run - 10 mm - t / 2,
                              cy=back_board_h / 2)
}

assembly cornhole {
    solid deck {
        board = Rectangle(center=(0, 0), width=deck_w, height=deck_l)
        hole target { c = Circle(center=(0, deck_l / 2 - 57 mm), diameter=38) }
        left_slots = tab_and_slot(part="slot", length=deck_l, thickness=t, tabs=3, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=-rail_x, cy=0)
        right_slots = tab_and_slot(part="slot", length=deck_l, thickness=t, tabs=3, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=rail_x, cy=0)
        drawing art {
            word = Text("CORNHOLE", position=(0, -deck_l / 2 + 60 mm), size=14,
                        font="sans:Bold", fill=true)
            ring = Circle(center=(0, deck_l / 2 - 57 mm), diameter=38 + 12)
        }
    }

    left = rail()
    right = rail()

    solid back {
        board = Rectangle(bottom_left=(-rail_x - t / 2, 0), width=2 * rail_x + t,
                          height=back_board_h)
        lt = tab_and_slot(part="tab", length=back_board_h, thickness=t, tabs=2, tab=15 mm,
                          screw=0, rotation=90 deg, cx=-rail_x - t / 2, cy=back_board_h / 2)
        rt = tab_and_slot(part="tab", length=back_board_h, thickness=t, tabs=2, tab=15 mm,
                          screw=0, rotation=-90 deg, cx=rail_x + t / 2, cy=back_board_h / 2)
    }

    # on the sheet
    RightOf(left, deck, gap=5)
    AlignTop(left, deck)
    Below(right, left, gap=5)
    AlignLeft(right, left)
    Below(back, right, gap=5)
    AlignLeft(back, right)

    # in 3D: x across, y from the front edge back, z up
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-rail_x - t / 2, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(rail_x - t / 2, 0, 0))
    # the deck's top face on the rails' top edges, its front edge over theirs
    Place(deck, rotation=(slope, 0, 0),
          position=(0, deck_l / 2 * cos(slope) + t * sin(slope),
                    front_h + deck_l / 2 * sin(slope) - t * cos(slope)))
    Place(back, rotation=(90 deg, 0, 0), position=(0, run - 10 mm, 0))

    assert deck.board.bb.width == 150 mm and deck.board.bb.height == 300 mm, "150 x 300 deck"
    assert deck.target.c.diameter == 38 mm, "38 mm hole"
    assert deck.board.bb.top - deck.target.c.center.y == 57 mm, "hole 57 mm below the top"
    assert left.side.points[3].y == 20 mm and left.side.points[2].y == 80 mm, "20 to 80 mm"
    assert deck.word.size == 14 mm, "14 mm letters"
    assert deck.word.position.y - deck.board.bb.bottom == 60 mm, "60 mm above the front"
    assert deck.ring.radius - deck.target.c.radius == 6 mm, "ring 6 mm outside the hole"
    assert back.board.bb.height == 65 mm, "65 mm back board"
    assert deck_w / 2 - (rail_x + t / 2) == 3 mm, "rails 3 mm in from the deck's edges"
}
