# Request: an NFPA 704 "fire diamond" for the store-room door where 35 % hydrogen peroxide is
# kept (health 2, flammability 0, instability 1, special OX). Layered 3 mm acrylic: a black
# back, a square of 250 mm side turned 45 degrees (corners r6), and on it four coloured
# diamonds of 115 mm side (corners r3), 4 mm apart and 8 mm in from the back's edges: blue
# (health) left, red (flammability) top, yellow (instability) right, white (special) bottom.
# Each rating is cut through its diamond as bold stencil characters, 60 mm tall (the special
# "OX" 40 mm), so the black shows through. Two 4.5 mm screw holes, 150 mm above and below the
# centre, through the back and the red and white diamonds, countersunk 9 mm in the diamonds.

units mm
thickness 3 mm

SIDE = 250 mm
Q = 115 mm
GAP = 4 mm
BORDER = 8 mm
D = (GAP / 2 + Q / 2) * sqrt(2)     # a coloured diamond's centre from the middle
MOUNT = 150 mm

def diamond(x=0 mm, y=0 mm, label="0", size=60 mm, mount=0 mm) -> solid {
    body = RoundedRectangle(center=(x, y), width=Q, height=Q, corner_radius=3,
                            rotation=45 deg)
    hole rating {
        t = Text(label, position=(x, y), size=size, font="sans:Bold", valign="middle",
                 stencil=true)
    }
    if mount != 0 {
        hole screw { c = Circle(center=(0, mount), diameter=4.5) }
        Countersink(screw, diameter=9 mm)
    }
}

assembly fire_diamond {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=SIDE, height=SIDE, corner_radius=6,
                                 rotation=45 deg)
        hole screws {
            top = Circle(center=(0, MOUNT), diameter=4.5)
            bottom = Circle(center=(0, -MOUNT), diameter=4.5)
        }
    }
    health = diamond(x=-D, y=0, label="2")
    fire = diamond(x=0, y=D, label="0", mount=MOUNT)
    instability = diamond(x=D, y=0, label="1")
    special = diamond(x=0, y=-D, label="OX", size=40 mm, mount=-MOUNT)

    # 3D: the coloured diamonds on the back, where they are drawn
    Place(back, position=(0, 0, 0))
    Place(health, position=(0, 0, 3))
    Place(fire, position=(0, 0, 3))
    Place(instability, position=(0, 0, 3))
    Place(special, position=(0, 0, 3))

    # the sheet: the coloured ones beside the back, in a row
    RightOf(health, back, gap=5)
    RightOf(fire, health, gap=5)
    Below(instability, health, gap=5)
    RightOf(special, instability, gap=5)
    AlignLeft(instability, health)

    # the request's numbers
    assert back.plate.width == 250 mm and health.body.width == 115 mm, "250 and 115 sides"
    # 8 mm in from the back's edges: along the diagonal the tips are sqrt(2) x 8 apart
    assert abs((SIDE / 2 * sqrt(2)) - (D + Q / 2 * sqrt(2)) - BORDER * sqrt(2)) < 0.001 mm,
        "8 mm border"
    assert abs(2 * D / sqrt(2) - Q - GAP) < 0.001 mm, "4 mm apart"
    assert fire.rating.t.size == 60 mm and special.rating.t.size == 40 mm, "60 / 40 mm"
    assert fire.screw.c.center.y - back.plate.center.y == 150 mm, "screw 150 above"
    assert special.screw.c.center.y - back.plate.center.y == -150 mm, "screw 150 below"
}
