# Request: a "maximum headroom 2.1 m" sign for a garage entrance, 300 mm across, layered
# from three discs of 3 mm acrylic. Bottom: a black disc. Middle: a white disc with the
# symbol cut out so the black shows through: two triangles 60 mm wide and 35 mm tall, the
# top one pointing down and the bottom one pointing up, their tips 90 mm apart, and
# "2.1 m" in bold sans letters 32 mm tall (at most 150 mm wide) between them. Top: a red
# ring 40 mm wide (hole 220 mm). Four 5.5 mm holes for M5 screws through all three layers
# on a 260 mm circle at 45, 135, 225 and 315 deg, countersunk 10 mm in the red ring.

t = 3 mm
thickness t

SIGN_D = 300 mm
RING_IN = 220 mm
BOLT_R = 130 mm
TRI_W = 60 mm
TRI_H = 35 mm
TIP_GAP = 90 mm
def bolt_at(a) = (BOLT_R * cos(a * 1 deg), BOLT_R * sin(a * 1 deg))

def layer(kind="black") -> solid {
    body = Circle(center=(0, 0), diameter=SIGN_D)
    hole mount {
        for a in [45, 135, 225, 315] {
            c = Circle(center=bolt_at(a), diameter=5.5)
        }
    }
    if kind == "white" {
        hole symbol {
            top_tri = Triangle(center=(0, TIP_GAP / 2 + TRI_H / 2), base=TRI_W, height=TRI_H,
                               rotation=180)
            bottom_tri = Triangle(center=(0, -(TIP_GAP / 2 + TRI_H / 2)), base=TRI_W,
                                  height=TRI_H)
            figure = Text("2.1 m", position=(0, 0), size=32, font="sans:Bold",
                          valign="middle", max_width=150)
        }
    }
    if kind == "red" {
        hole window {
            w = Circle(center=(0, 0), diameter=RING_IN)
        }
        Countersink(mount, diameter=10)
    }
}

assembly headroom_sign {
    black = layer(kind="black")
    white = layer(kind="white")
    red = layer(kind="red")

    # flat on the sheet
    RightOf(white, black, gap=10)
    AlignTop(white, black)
    RightOf(red, white, gap=10)
    AlignTop(red, white)

    # in 3D: stacked, black at the back
    Place(black, position=(0, 0, 0))
    Place(white, position=(0, 0, t))
    Place(red, position=(0, 0, 2 * t))

    assert black.body.diameter == 300 mm and white.body.diameter == 300 mm and
        red.body.diameter == 300 mm, "300 mm discs"
    assert (red.body.diameter - red.window.w.diameter) / 2 == 40 mm, "ring 40 wide"
    assert white.symbol.top_tri.bb.bottom - white.symbol.bottom_tri.bb.top == 90 mm,
        "tips 90 apart"
    assert white.symbol.top_tri.base == 60 mm and white.symbol.top_tri.height == 35 mm,
        "triangles 60 x 35"
    assert white.symbol.figure.bb.width <= 150 mm, "figure at most 150 wide"
    assert distance(white.symbol.figure, white.symbol.top_tri) >= 10 mm, "figure clear of the tips"
    # the symbol must show inside the red ring's window
    assert distance(white.symbol.top_tri.b, (0, 0)) <= RING_IN / 2 - 10 mm, "symbol inside the window"
    assert distance(red.mount.c[0].center, red.mount.c[2].center) == 260 mm, "260 circle"
    assert BOLT_R - 2.75 mm >= RING_IN / 2 + 5 mm and BOLT_R + 2.75 mm <= SIGN_D / 2 - 5 mm,
        "holes inside the ring"
    assert len(red.mount.c) == 4, "four screws"
}
