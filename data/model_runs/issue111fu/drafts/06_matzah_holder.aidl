# Request: a Passover matzah holder, 6 mm birch ply, open at the front.
# - Two side panels 200 mm deep, straight sides 160 mm tall, then an arched top rising to
#   215 mm at the middle; a Star of David cut out of the arch (two triangles, 36 mm tip to
#   tip), its centre 185 mm up; on the outside of each side, fill-engraved beside its
#   compartment, serif 12 mm: KOHEN (top), LEVI, YISRAEL (bottom), centred front to back.
# - Four boards 200 x 200 mm between the sides (bottom, two dividers, top), each with two
#   50 mm tabs on each end through mortises in the sides (0.1 mm clearance in the mortise),
#   the boards' undersides at 10, 56, 102 and 148 mm: three 40 mm compartments for the matzot.
# - "CHAG SAMEACH" fill-engraved on the top board, serif 14 mm, centred.

import "std/joints.aidl"

units mm
thickness 6 mm

T = 6 mm
HEIGHTS = [10, 56, 102, 148]         # the boards' undersides
LABELS = ["YISRAEL", "LEVI", "KOHEN"]  # bottom compartment first

def side() -> solid {
    l1 = Line((-100, 0), (100, 0))
    l2 = Line((100, 0), (100, 160))
    top = Arc(start=(100, 160), through=(0, 215), end=(-100, 160))
    l3 = Line((-100, 160), (-100, 0))
    for i in range(4) {
        m = tab_and_slot(part="slot", length=200, thickness=T, tabs=2, tab=50, screw=0,
                         clearance=0.1, cx=0, cy=HEIGHTS[i] + T / 2)
    }
    hole star {
        up = RegularPolygon(center=(0, 185), radius=18, sides=3, rotation=90 deg)
        down = RegularPolygon(center=(0, 185), radius=18, sides=3, rotation=270 deg)
    }
    drawing names {
        for i in range(3) {
            t = Text(LABELS[i], position=(0, HEIGHTS[i] + T + 20), size=12, font="serif",
                     valign="middle", fill=true)
        }
    }
    Fixed([l1, l2, top, l3])
    assert l1.length == 200 mm, "200 deep"
    assert l2.length == 160 mm, "straight sides 160"
    assert top.through.y == 215 mm, "arch to 215"
    assert star.bb.height == 36 mm, "star 36 tip to tip"
    assert star.up.center.y == 185 mm, "star centred 185 up"
    assert distance(star, top) >= 5 mm, "star inside the arch"
    assert m[1].slot[0].bb.center_y - m[0].slot[0].bb.center_y == 40 mm + T, "40 mm compartments"
    assert distance(names.t[2], m[3]) >= 5 mm and distance(names.t[2], m[2]) >= 5 mm, "KOHEN clear of the mortises"
    assert distance(names.t[0], m[0]) >= 5 mm, "YISRAEL clear of the mortises"
    assert names.t[0].size == 12 mm, "12 mm names"
}

def board() -> solid {
    plank = Rectangle(center=(0, 0), width=200 + 2 * T, height=200)
    right_end = tab_and_slot(part="tab", length=200, thickness=T, tabs=2, tab=50, screw=0,
                             rotation=-90 deg, cx=100 + T, cy=0)
    left_end = tab_and_slot(part="tab", length=200, thickness=T, tabs=2, tab=50, screw=0,
                            rotation=90 deg, cx=-100 - T, cy=0)
    Fixed(plank)
    assert plank.height == 200 mm, "200 front to back"
}

assembly matzah_holder {
    left = side()
    right = side()
    for i in range(4) {
        b = board()
    }
    drawing greeting {
        g = Text("CHAG SAMEACH", position=(0, 0), size=14, font="serif", valign="middle",
                 fill=true)
    }
    CenterInside(greeting, b[3].plank)
    CutInto(greeting, b[3])

    # flat on the sheet
    RightOf(right, left, gap=10)
    AlignBottom(right, left)
    Below(b[0], left, gap=10)
    AlignLeft(b[0], left)
    for i in range(1, 4) {
        RightOf(b[i], b[i - 1], gap=10)
        AlignBottom(b[i], b[i - 1])
    }

    # assembled: the sides stand at the boards' ends, the boards between them
    Place(left, position=(-100, 0, 0), face="left", up="up")
    Place(right, position=(100, 0, 0), face="right", up="up")
    for i in range(4) {
        Place(b[i], position=(0, 0, HEIGHTS[i]))
    }

    assert len(b) == 4, "four boards"
    assert b[0].right_end.gap[0].bb.width == T, "tabs as long as the side is thick"
    assert greeting.g.size == 14 mm, "14 mm greeting"
}
