# Request (music): a pickguard for a home-built two-pickup electric guitar, 3 mm black
# acrylic. A smooth outline 255 mm long and 130 mm tall (from y -44 to 86) with a straight
# 70 mm edge at the neck end (two sharp corners), otherwise one flowing curve; two
# single-coil pickup openings 18 x 85 mm with R2 corners, centres 50 mm apart (neck pickup
# 105 mm from the neck edge), both centred at y 21; two 9.5 mm pot holes (volume and
# tone); eight 3.2 mm holes for countersunk No. 4 wood screws (6.5 mm heads), about 7 mm in
# from the edge; "K.R. 2026" engraved between the neck edge and the neck pickup.

thickness 3 mm

pickup_w = 18 mm
pickup_l = 85 mm
pickup_y = 21 mm
screw_at = [(7, -12), (7, 42), (45, 70), (110, 78), (190, 66), (244, 12), (150, -36), (60, -30)]

solid pickguard {
    outline = Spline([(0, -20), (0, 50), (40, 78), (110, 86), (190, 74), (250, 30), (255, 0),
                      (235, -30), (150, -44), (60, -38)], closed=true, corners=[0, 1])
    Fixed(outline)

    hole pickups {
        neck = RoundedRectangle(center=(105, pickup_y), width=pickup_w, height=pickup_l, corner_radius=2)
        bridge = RoundedRectangle(center=(155, pickup_y), width=pickup_w, height=pickup_l, corner_radius=2)
    }
    hole pots {
        volume = Circle(center=(205, 35), diameter=9.5)
        tone = Circle(center=(215, 5), diameter=9.5)
    }
    hole screws {
        for i in range(len(screw_at)) {
            c = Circle(center=screw_at[i], diameter=3.2)
        }
    }
    Countersink(screws, diameter=6.5)

    drawing label {
        t = Text("K.R. 2026", (48, pickup_y), size=5, valign="middle")
    }

    assert abs(pickups.bridge.center.x - pickups.neck.center.x - 50 mm) < 0.001 mm, "pickups 50 mm apart"
    assert abs(pickups.neck.center.x - outline.points[0].x - 105 mm) < 0.001 mm, "neck pickup 105 mm from the neck edge"
    assert pickups.neck.width == 18 mm and pickups.neck.height == 85 mm, "18 x 85 openings"
    assert len(screws.c) == 8, "eight screws"
    assert outline.points[1].y - outline.points[0].y == 70 mm, "70 mm neck edge"
    assert label.bb.right < pickups.bb.left - 3 mm, "label clear of the neck pickup"
}
