# Table-saw featherboard, 6 mm birch plywood. A board 70 mm wide whose bottom long edge
# is 240 mm and whose right end is cut at 60 degrees to the long edges (leaning back, so
# the top edge is shorter). Thirteen fingers-cuts parallel to the long edges, 2.5 mm wide,
# on a 5 mm pitch (the first 5 mm above the bottom edge), each reaching 60 mm back from
# the angled end (round inner ends) and open through the angled end: the strips between
# them are the springy fingers. Two mounting slots for 6 mm bolts, 6.5 mm wide and 70 mm
# long (tip to tip), parallel to the length, from 20 mm to 90 mm along, 20 mm and 50 mm
# above the bottom edge. "FEED" engraved 6 mm tall, centred between the two slots.
# Corners at the square end rounded 5 mm.

units mm
thickness 6 mm

param cuts = 13, min = 5, max = 13
param pitch = 5 mm, min = 4 mm, max = 6 mm

W = 70 mm
L = 240 mm
run = W / tan(60 deg)    # how far the angled end leans back over the width

solid feather {
    board = Polygon([(0, 0), (L, 0), (L - run, W), (0, W)])
    Fillet(board.points[0], 5)
    Fillet(board.points[3], 5)

    hole fingers {
        for i in range(cuts) {
            s = Slot(start=(L - (5 + i * pitch) / tan(60 deg) - 60, 5 + i * pitch),
                     end=(L - (5 + i * pitch) / tan(60 deg) + 3, 5 + i * pitch), width=2.5)
        }
    }

    hole mount {
        lo = Slot(center=(55, 20), length=70, width=6.5)
        hi = Slot(center=(55, 50), length=70, width=6.5)
    }

    drawing label {
        t = Text("FEED", (55, 35), size=6, valign="middle")
    }

    assert board.bb.width == 240 mm and board.bb.height == 70 mm, "240 long, 70 wide"
    assert abs(degrees(atan2(board.points[2].y - board.points[1].y, board.points[1].x - board.points[2].x)) - 60) < 0.01, "end at 60 deg"
    assert len(fingers.s) == 13, "13 cuts"
    assert fingers.s[1].start.y - fingers.s[0].start.y == 5 mm, "5 mm pitch"
    assert fingers.s[0].start.y - board.bb.bottom == 5 mm, "first 5 mm up"
    assert fingers.s[0].width == 2.5 mm, "2.5 mm wide"
    assert min([(L - s.start.y / tan(60 deg)) - s.start.x for s in fingers.s]) == 60 mm, "60 mm back from the end"
    assert mount.lo.length == 70 mm and mount.lo.width == 6.5 mm, "70 x 6.5 slots"
    assert mount.lo.bb.left == 20 mm and mount.lo.bb.right == 90 mm, "20 to 90 along"
    assert mount.lo.center.y == 20 mm and mount.hi.center.y == 50 mm, "20 and 50 up"
    assert label.t.size == 6 mm, "6 mm text"
}
