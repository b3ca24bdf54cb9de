# Gifts: a hinged jewellery box, 3 mm plywood, 140 x 90 x 50 mm outside (the lid 140 x 90),
# 10 mm fingers, the lid on pins cut from the sheet. Engraved on the lid: "FOR ANNA", 10 mm
# high, and above it a heart outline 20 mm wide and 17 mm tall (two R5 arcs side by side over a
# V down to a point 12 mm below the arcs' centres), the heart's point 8 mm above the top of the
# letters; heart and name together centred on the lid. A finger notch: a R10 half circle cut
# into the top edge of the front wall, centred along it.
units mm
thickness 3 mm
import "std/boxes.aidl"

assembly gift {
    box = hinged_box(length=140 mm, width=90 mm, height=50 mm, thickness=3 mm, finger=10 mm)

    drawing inscription {
        word = Text("FOR ANNA", (0, 0), size=10)
        left_lobe = Arc(center=(-5, 30), radius=5, start_angle=0 deg, end_angle=180 deg)
        right_lobe = Arc(center=(5, 30), radius=5, start_angle=0 deg, end_angle=180 deg)
        tip = Point(0, 18)
        v_left = Line((-10, 30), (0, 18))
        v_right = Line((10, 30), (0, 18))
        Coincident(v_left.start, left_lobe.end)
        Coincident(v_right.start, right_lobe.start)
        Coincident(v_left.end, tip)
        Coincident(v_right.end, tip)
    }
    Rigid(inscription)
    CenterInside(inscription, box.lid)
    CutInto(inscription, box.lid)

    hole notch {
        c = Circle(center=(0, 0), radius=10)
    }
    notch.c.center.y == box.front.bb.top
    notch.c.center.x == box.front.bb.center_x
    CutInto(notch, box.front)

    assert max(box.lid.bb.width, box.lid.bb.height) == 140 mm, "lid 140 long"
    assert min(box.lid.bb.width, box.lid.bb.height) == 90 mm, "lid 90 wide"
    assert inscription.word.size == 10 mm, "name 10 mm"
    assert inscription.right_lobe.bb.right - inscription.left_lobe.bb.left == 20 mm, "heart 20 wide"
    assert inscription.left_lobe.bb.top - inscription.tip.y == 17 mm, "heart 17 tall"
    assert inscription.left_lobe.center.y - inscription.tip.y == 12 mm, "point 12 below the arcs' centres"
    assert inscription.tip.y - (inscription.word.position.y + 10 mm) == 8 mm, "point 8 above the letters' top"
    assert abs(inscription.bb.center_x - box.lid.bb.center_x) < 0.01 mm, "centred on the lid"
    assert abs(inscription.bb.center_y - box.lid.bb.center_y) < 0.01 mm, "centred on the lid"
    assert notch.c.radius == 10 mm, "R10 notch"
    assert notch.c.center.y == box.front.bb.top, "notch on the front's top edge"
    assert notch.c.center.x == box.front.bb.center_x, "notch centred"
}
