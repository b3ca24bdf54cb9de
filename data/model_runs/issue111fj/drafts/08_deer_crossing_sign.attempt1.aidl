# Request: a two-colour layered "deer crossing" warning sign for our farm lane, 3 mm cast
# acrylic. A yellow diamond backing 500 mm corner to corner (a square on its point),
# corners R20, with two 8.5 mm holes on its vertical centre line 160 mm above and 175 mm
# below the centre for M8 bolts to the post. Glued on it, cut from black: a border ring
# 14 mm wide whose outer edge is 10 mm in from the backing's edge (outer diamond 480 corner
# to corner), corners R12; a leaping deer (facing right, antlers, about 180 x 180 mm,
# corners eased R2, a 4 mm eye hole so the yellow shows), centred 10 mm above the centre;
# and a black plate 160 x 46 mm (R6) 110 mm below the centre with "SLOW" cut through it as a
# stencil (sans bold, 30 mm, at most 140 wide) so the yellow shows through the letters.

units mm
thickness 3 mm

BACK_R = 250 mm            # centre to corner
RING_OUT = 240 mm
RING_W = 14 mm
RING_IN = RING_OUT - RING_W * sqrt(2)

assembly deer_sign {
    solid backing {
        body = RegularPolygon(center=(0, 0), radius=BACK_R, sides=4)
        hole top_bolt { c = Circle(center=(0, 160 mm), diameter=8.5 mm) }
        hole bottom_bolt { c = Circle(center=(0, -175 mm), diameter=8.5 mm) }
        Fillet(body, 20 mm)
        assert body.bb.height == 500 mm, "500 corner to corner"
    }

    solid border {
        outer = RegularPolygon(center=(0, 0), radius=RING_OUT, sides=4)
        hole inner { d = RegularPolygon(center=(0, 0), radius=RING_IN, sides=4) }
        Fillet(12 mm)
        assert (RING_OUT - RING_IN) / sqrt(2) == 14 mm, "ring 14 wide"
        assert BACK_R - RING_OUT == 10 mm * sqrt(2), "10 mm of yellow outside the ring"
    }

    solid deer {
        body = Polygon([(-95, 36), (-74, 26), (-45, 30), (-10, 33), (20, 42), (35, 58),
                        (42, 72), (34, 86), (47, 79), (40, 104), (50, 88), (53, 106),
                        (57, 85), (79, 70), (82, 62), (62, 58), (50, 42), (44, 28),
                        (64, 14), (74, -10), (66, -12), (56, 6), (32, 12), (0, 8),
                        (-28, 6), (-36, -10), (-56, -40), (-76, -72), (-88, -69),
                        (-70, -38), (-62, -18), (-72, 0), (-80, 18)])
        hole eye { c = Circle(center=(62, 68), diameter=4 mm) }
        Fillet(2 mm)
    }

    solid slow_plate {
        body = RoundedRectangle(center=(0, 0), width=160, height=46, corner_radius=6)
        hole word {
            t = Text("SLOW", position=(0, 0), size=30, font="sans:Bold", valign="middle",
                     stencil=true, max_width=140 mm)
        }
    }

    # flat layout for cutting
    RightOf(border, backing, gap=10)
    AlignTop(border, backing)
    RightOf(deer, border, gap=10)
    AlignTop(deer, border)
    Below(slow_plate, deer, gap=10)
    AlignLeft(slow_plate, deer)

    # 3D: the backing standing up facing the lane, the black pieces glued on its face
    Place(backing, position=(0, 0, 0), face="front", up="up")
    Place(border, on=backing, position=(0, 0), face="up")
    Place(deer, on=backing, position=(0, 10 mm), face="up")
    Place(slow_plate, on=backing, position=(0, -110 mm), face="up")
}
