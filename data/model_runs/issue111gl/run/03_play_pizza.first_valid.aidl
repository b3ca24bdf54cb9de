# Request: a toy pizza for my niece's play kitchen. From 6 mm poplar ply: a 240 mm pizza
# cut into 8 slices, each with the crust line engraved as an arc 15 mm in from the edge; a
# 260 mm serving board with a 50 x 100 mm handle (12 mm corners, 10 mm fillets where it
# meets the board), an 18 mm hanging hole 20 mm from the handle's end and "NONNA" engraved
# filled (sans Bold) along the handle; and an 8 mm rim ring glued on the board (260 mm
# outside) that leaves 2 mm round the pizza. From 3 mm ply, the toppings: 8 pepperoni discs
# 30 mm across with three engraved 4 mm spots, and 4 mushroom slices (a 24 mm half-round
# cap on an 8 x 12 mm stem). Assembled: the slices in the rim, a pepperoni on each slice
# and the mushrooms on every other one.

units mm
t = 6 mm
tt = 3 mm
thickness t

pizza_d = 240 mm
slices = 8
crust = 15 mm
board_d = 260 mm
rim_w = 8 mm
pep_d = 30 mm
peps = 8
mushrooms = 4
wedge = 360 deg / slices

def pizza_slice(a=0 deg) -> solid {
    wedge_shape = Sector(center=(0, 0), radius=pizza_d / 2, start_angle=a, end_angle=a + wedge)
    drawing crust_line {
        edge = Arc(center=(0, 0), radius=pizza_d / 2 - crust, start_angle=a + 3 deg,
                   end_angle=a + wedge - 3 deg)
    }
}

def pepperoni() -> solid {
    thickness tt
    disc = Circle(center=(0, 0), diameter=pep_d)
    drawing spots {
        for k in range(3) {
            dot = Circle(center=(7 mm * cos(k * 120 deg + 90 deg), 7 mm * sin(k * 120 deg + 90 deg)),
                         diameter=4)
        }
    }
}

def mushroom() -> solid {
    thickness tt
    cap = Sector(center=(0, 0), radius=12, start_angle=0 deg, end_angle=180 deg)
    stem = RoundedRectangle(center=(0, -5), width=8, height=12, corner_radius=2)
}

assembly pizza_set {
    solid board {
        disc = Circle(center=(0, 0), diameter=board_d)
        grip = RoundedRectangle(center=(0, -board_d / 2 - 40), width=50, height=100,
                                corner_radius=12)
        hole hang { c = Circle(center=(0, -board_d / 2 - 70), diameter=18) }
        Fillet([grip, disc], 10)
        drawing name {
            word = Text("NONNA", position=(0, -board_d / 2 - 28), size=12, font="sans:Bold",
                        fill=true, valign="middle", rotation=90 deg, max_width=48)
        }
        assert grip.width == 50 mm and grip.height == 100 mm, "handle 50 x 100"
        assert hang.c.center.y - grip.bb.bottom == 20 mm, "hanging hole 20 mm from the end"
        assert distance(name, hang) >= 3 mm, "the name clear of the hanging hole"
    }
    solid rim {
        ring = Circle(center=(0, 0), diameter=board_d)
        hole inner { c = Circle(center=(0, 0), diameter=board_d - 2 * rim_w) }
    }
    for i in range(slices) {
        piece = pizza_slice(a=i * wedge)
        Place(piece, position=(0, 0, t))
    }
    for i in range(peps) {
        pep = pepperoni()
        pep.disc.center == (-105 mm + i * 35 mm, -150 mm)
        Place(pep, position=(75 mm * cos((i + 0.5) * wedge), 75 mm * sin((i + 0.5) * wedge), 2 * t))
    }
    for k in range(mushrooms) {
        mush = mushroom()
        mush.cap.center == (-90 mm + k * 32 mm, -190 mm)
        Place(mush, position=(38 mm * cos((2 * k + 1.5) * wedge), 38 mm * sin((2 * k + 1.5) * wedge), 2 * t))
    }

    # flat: the slices stay together as a pizza, the board left of it, the rim right
    LeftOf(board, piece[4], gap=15)
    AlignCenterY(board.disc, piece[0].wedge_shape.center)
    RightOf(rim, piece[0], gap=15)
    AlignCenterY(rim.ring, piece[0].wedge_shape.center)

    # assembled: board, rim on it, the slices inside the rim
    Place(board, position=(0, 0, 0))
    Place(rim, position=(0, 0, t))

    assert len(piece) == 8, "8 slices"
    assert piece[0].wedge_shape.radius * 2 == 240 mm, "a 240 mm pizza"
    assert board.disc.diameter == 260 mm and rim.ring.diameter == 260 mm, "260 mm board and rim"
    assert (rim.inner.c.diameter - 240 mm) / 2 == 2 mm, "2 mm round the pizza"
    assert len(pep) == 8 and pep[0].disc.diameter == 30 mm, "8 pepperoni of 30 mm"
    assert len(mush) == 4, "4 mushrooms"
    assert 75 mm + pep_d / 2 <= pizza_d / 2 - crust, "pepperoni inside the crust"
}
