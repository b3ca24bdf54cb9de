# Request: a string-and-bead disentanglement puzzle ("free the ring") for my nephew, cut
# from 4 mm birch ply and threaded with 3 mm cord. Four pieces:
# - a board 120 x 40 mm with R8 corners and three 10 mm holes on its long centre line, the
#   middle one at the centre and the others 40 mm either side; "FREE THE RING" engraved
#   (filled, bold, 4 mm tall) between the holes and the top edge;
# - two beads, each a six-petal flower: petals reaching 14 mm from the centre as a sharp
#   star (rounded R3), the notches between them 10 mm from the centre, a 4 mm cord hole in
#   the middle: too big to pass the 10 mm holes or the ring;
# - a ring 32 mm across with a 16 mm hole: too big to pass the board's holes.
# Laid out for cutting: the board on top, the beads and the ring in a row under it.

import "std/shapes.aidl"

units mm
thickness 4 mm
kerf 0.15 mm

hole_d = 10 mm
pitch = 40 mm

def flower_bead() -> solid {
    petals = Star(center=(0, 0), points=6, outer_radius=14, inner_radius=10, tip_radius=3)
    hole cord { c = Circle(center=(0, 0), diameter=4) }
}

assembly ring_puzzle {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=120, height=40, corner_radius=8)
        hole holes {
            for i in range(3) {
                c = Circle(center=((i - 1) * pitch, 0), diameter=hole_d)
            }
        }
        drawing title {
            t = Text("FREE THE RING", position=(0, 12.5), size=4, font="sans:Bold",
                     valign="middle", fill=true)
        }
        Fixed(body)
    }
    bead_a = flower_bead()
    bead_b = flower_bead()
    ring = washer(outer=32 mm, inner=16 mm)

    Below(bead_a, board, gap=5)
    AlignLeft(bead_a, board)
    RightOf(bead_b, bead_a, gap=5)
    AlignTop(bead_b, bead_a)
    RightOf(ring, bead_b, gap=5)
    AlignTop(ring, bead_b)

    assert board.body.width == 120 mm and board.body.height == 40 mm
    assert len(board.holes.c) == 3
    assert board.holes.c[0].diameter == 10 mm
    assert board.holes.c[1].center.x - board.body.center.x == 0 mm, "middle hole at the centre"
    assert board.holes.c[2].center.x - board.holes.c[1].center.x == 40 mm
    assert board.holes.c[1].center.x - board.holes.c[0].center.x == 40 mm
    assert board.title.t.size == 4 mm
    assert distance(board.title, board.holes) >= 1 mm, "title clear of the holes"
    assert board.title.bb.top <= board.body.bb.top - 1 mm, "title on the board"
    assert bead_a.petals.outer_radius == 14 mm and bead_a.petals.inner_radius == 10 mm
    assert bead_a.cord.c.diameter == 4 mm
    # the puzzle only works if the beads pass neither the board's holes nor the ring
    assert 2 * bead_a.petals.inner_radius > 16 mm and 2 * bead_a.petals.inner_radius > 10 mm
    assert ring.outer == 32 mm and ring.inner == 16 mm
    assert ring.inner > 4 mm and ring.outer - ring.inner > 10 mm
}
