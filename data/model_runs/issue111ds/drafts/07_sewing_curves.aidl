# Request (crafts, dressmaking): a set of three pattern-drafting curves in 3 mm clear
# acrylic, each with a 6 mm hole to hang it on the pegboard, all corners softened R2.
# 1. A hip curve 300 long x about 46 tall: a straight bottom edge with a centimetre scale
#    engraved on it (zero 20 mm from the left end, a tick every 10 mm, 4 mm long, 8 mm
#    every 50 mm, numbered 0, 5, 10 ... 25 in 4 mm figures) under a long gentle curve;
#    "HIP" engraved, 5 mm.
# 2. A French curve about 205 x 120 with a curved window cut inside it; "FRENCH" 5 mm.
# 3. An armhole curve, a comma about 110 x 125; "ARM" 5 mm along its tail.
# The curves' points are the drafting shapes I traced; the hanging holes keep at least
# 6 mm of material round them.

thickness 3 mm

assembly sewing_curves {
    solid hip {
        edge = Spline([(0, 0), (300, 0), (280, 14), (230, 32), (160, 44), (90, 46), (40, 38),
                       (12, 22)], closed=true, corners=[0, 1])
        hole hang { c = Circle(center=(45, 28), diameter=6) }
        drawing scale {
            for i in range(28) {
                tick = Line(start=(20 + i * 10, 0), length=8 if i % 5 == 0 else 4, angle=90 deg)
            }
            for k in range(6) {
                fig = Text(str(k * 5), position=(20 + k * 50, 11), size=4)
            }
            name = Text("HIP", position=(150, 24), size=5)
        }
        # FIX after the first valid program: Fillet(2 mm) left both ends sharp (W0406 said
        # the outline had no corners; the picture shows two), and naming them is E0407
        # (a Spline's corners= cannot be filleted): round the convex corners by shrinking
        # the outline 2 mm and growing it back 2 mm with round joins
        soft = Offset(Inset(edge, 2 mm), 2 mm, join="round")
    }

    solid french {
        edge = Spline([(0, 0), (50, -12), (110, -8), (165, 15), (200, 55), (195, 95),
                       (170, 108), (150, 90), (135, 62), (105, 42), (65, 32), (25, 28),
                       (-5, 15)], closed=true)
        hole window {
            w = Spline([(60, 8), (110, 10), (150, 30), (165, 55), (155, 60), (130, 40),
                        (100, 24), (65, 20)], closed=true)
        }
        hole hang { c = Circle(center=(20, 14), diameter=6) }
        drawing label { name = Text("FRENCH", position=(178, 78), size=5, rotation=80 deg) }
    }

    solid armhole {
        edge = Spline([(0, 0), (40, -5), (80, 10), (105, 45), (105, 90), (90, 120), (75, 118),
                       (82, 85), (75, 50), (50, 25), (15, 18), (-5, 10)], closed=true)
        hole hang { c = Circle(center=(18, 7), diameter=6) }
        drawing label { name = Text("ARM", position=(93, 62), size=5, rotation=85 deg) }
    }

    # on the sheet
    Below(french, hip, gap=8)
    AlignLeft(french, hip)
    RightOf(armhole, french, gap=8)
    AlignTop(armhole, french)

    # the request's numbers
    assert hip.edge.points[1].x - hip.edge.points[0].x == 300 mm, "hip curve 300 long"
    assert hip.scale.tick[0].start.x - hip.edge.points[0].x == 20 mm, "zero 20 mm in"
    assert hip.scale.tick[1].start.x - hip.scale.tick[0].start.x == 10 mm, "a tick every 10"
    assert hip.scale.tick[5].length == 8 mm and hip.scale.tick[1].length == 4 mm, "tick lengths"
    assert len(hip.scale.fig) == 6, "0 to 25"
    assert hip.hang.c.diameter == 6 mm and french.hang.c.diameter == 6 mm and
        armhole.hang.c.diameter == 6 mm, "6 mm holes"
}
