# Request (sport): a climbing finger-training hangboard laminated from four layers of 6 mm birch
# ply, screwed to the wall above a doorway.
# - Back plate 500 x 220 mm (10 mm corner radius) with four 6.5 mm holes for M6 countersunk wood
#   screws (12 mm heads) at x = +-200 mm, 15 mm in from the top and bottom edges.
# - Three layers 500 x 160 mm (10 mm corner radius) glued on its middle: the front, a first core
#   and a second core (next to the back).
# - Holds, all with 8 mm corner radius in plan: a 420 x 40 mm jug 15 mm below the stack's top edge,
#   cut through the front and both cores (18 mm deep); below it two 180 x 30 mm edges, and below
#   those four pockets 30 mm tall (3-finger 60 mm wide at the ends, 2-finger 45 mm wide inside),
#   cut through the front and the first core (12 mm deep); 15 mm of ply between rows.
# - On the front, engraved 5 mm tall under each hold: "JUG 18", "EDGE 12", "3F" / "2F".

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 9 mm
w = 500 mm
h = 160 mm
row_gap = 15 mm
jug_y = h / 2 - 15 mm - 20 mm
edge_y = jug_y - 20 mm - row_gap - 15 mm
pocket_y = edge_y - 15 mm - row_gap - 15 mm

def layer(small=true) -> solid {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=10)
    hole jug { r = RoundedRectangle(center=(0, jug_y), width=420, height=40, corner_radius=8) }
    if small {
        hole edges {
            l = RoundedRectangle(center=(-110, edge_y), width=180, height=30, corner_radius=8)
            r = RoundedRectangle(center=(110, edge_y), width=180, height=30, corner_radius=8)
        }
        hole pockets {
            p3l = RoundedRectangle(center=(-170, pocket_y), width=60, height=30, corner_radius=8)
            p2l = RoundedRectangle(center=(-80, pocket_y), width=45, height=30, corner_radius=8)
            p2r = RoundedRectangle(center=(80, pocket_y), width=45, height=30, corner_radius=8)
            p3r = RoundedRectangle(center=(170, pocket_y), width=60, height=30, corner_radius=8)
        }
    }
}

assembly hangboard {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=w, height=220, corner_radius=10)
        hole screws {
            a = Circle(center=(-200, 110 - 15), diameter=6.5)
            b = Circle(center=(200, 110 - 15), diameter=6.5)
            c = Circle(center=(-200, -110 + 15), diameter=6.5)
            d = Circle(center=(200, -110 + 15), diameter=6.5)
        }
        Countersink(screws, diameter=12)
    }
    solid front {
        l = layer(small=true)
        drawing labels {
            jug = Text("JUG 18", (0, jug_y - 20 - row_gap / 2), size=5, valign="middle")
            e1 = Text("EDGE 12", (-110, edge_y - 15 - row_gap / 2), size=5, valign="middle")
            e2 = Text("EDGE 12", (110, edge_y - 15 - row_gap / 2), size=5, valign="middle")
            q1 = Text("3F", (-170, pocket_y - 15 - row_gap / 2), size=5, valign="middle")
            q2 = Text("2F", (-80, pocket_y - 15 - row_gap / 2), size=5, valign="middle")
            q3 = Text("2F", (80, pocket_y - 15 - row_gap / 2), size=5, valign="middle")
            q4 = Text("3F", (170, pocket_y - 15 - row_gap / 2), size=5, valign="middle")
        }
    }
    core1 = layer(small=true)
    core2 = layer(small=false)

    # flat for cutting
    Below(front, back, gap=6)
    AlignLeft(front, back)
    Below(core1, front, gap=6)
    AlignLeft(core1, front)
    Below(core2, core1, gap=6)
    AlignLeft(core2, core1)
    # glued up on the wall: back, second core, first core, front
    Place(back, position=(0, 0, 0))
    Place(core2, position=(0, 0, t))
    Place(core1, position=(0, 0, 2 * t))
    Place(front, position=(0, 0, 3 * t))

    # the request's numbers
    assert back.body.bb.width == 500 mm and back.body.bb.height == 220 mm, "back 500 x 220"
    assert front.l.body.bb.width == 500 mm and front.l.body.bb.height == 160 mm, "stack 500 x 160"
    assert back.screws.b.center.x == 200 mm and back.body.bb.top - back.screws.b.center.y == 15 mm,
        "screws at x 200, 15 in"
    assert front.l.body.bb.top - front.l.jug.r.bb.top == 15 mm, "jug 15 below the top"
    assert front.l.jug.r.width == 420 mm and front.l.jug.r.height == 40 mm, "jug 420 x 40"
    assert front.l.jug.r.bb.bottom - front.l.edges.l.bb.top == 15 mm, "15 between rows"
    assert front.l.edges.l.bb.bottom - front.l.pockets.p3l.bb.top == 15 mm, "15 between rows"
    assert front.l.edges.l.width == 180 mm and front.l.edges.l.height == 30 mm, "edges 180 x 30"
    assert front.l.pockets.p3l.width == 60 mm and front.l.pockets.p2l.width == 45 mm, "3F 60, 2F 45"
    assert front.l.pockets.p3l.bb.bottom > front.l.body.bb.bottom, "pockets on the board"
    assert 3 * t == 18 mm and 2 * t == 12 mm, "depths 18 and 12"
}
