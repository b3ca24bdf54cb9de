# Keepsake gift box (gifts). Full sizes: a finger-jointed box with a lift-off lid, 120 x 90 x
# 60 mm outside (lid included), 3 mm ply, 10 mm fingers, 0.3 mm lip clearance (std lid_box).
# In the lid: a heart 40 mm wide and 35 mm high cut through (the lip glued under it stays
# whole, so the heart shows as a recess), centred across the lid, its centre 8 mm above the
# lid's middle; made of two 21 mm round lobes and a point. Under the heart "FOR MIA"
# engraved 8 mm high, centred, its top 8 mm below the heart's lowest point.

import "std/boxes.aidl"

units mm
thickness 3 mm

assembly gift {
    box = lid_box(length=120 mm, width=90 mm, height=60 mm, thickness=3 mm, finger=10 mm,
                  clearance=0.3 mm)

    hole heart {
        l = Circle(center=(-9.5, 8), radius=10.5)
        r = Circle(center=(9.5, 8), radius=10.5)
        tip = Circle(center=(0, -16), radius=0.5)
        left_half = Hull(l, tip)
        right_half = Hull(r, tip)
    }
    Rigid(heart)
    AlignCenterX(heart, box.lid)
    heart.bb.center_y == box.lid.bb.center_y + 8
    CutInto(heart, box.lid)

    drawing name {
        t = Text("FOR MIA", position=(0, -30), size=8)
    }
    AlignCenterX(name, box.lid)
    name.bb.top == heart.bb.bottom - 8
    CutInto(name, box.lid)

    assert heart.bb.width == 40 mm, "heart 40 mm wide"
    assert heart.bb.height == 35 mm, "heart 35 mm high"
    assert heart.l.diameter == 21 mm, "21 mm lobes"
    assert heart.bb.center_y - box.lid.bb.center_y == 8 mm, "heart 8 mm above the lid's middle"
    assert heart.bb.center_x == box.lid.bb.center_x, "heart centred across"
    assert name.t.size == 8 mm, "name 8 mm high"
    assert heart.bb.bottom - name.bb.top == 8 mm, "name 8 mm under the heart"
    assert box.lid.bb.width == 120 mm and box.lid.bb.height == 90 mm, "lid 120 x 90"
    assert name.bb.bottom > box.lid.bb.bottom + 5 mm, "name inside the lid"
}
