# Signs (science): a lab door sign, 3 mm acrylic, 200 x 80 mm with 8 mm
# rounded corners (backed by a coloured sheet). "LAB 3" cut through as
# stencil letters (sans Bold outlines, 40 mm cap height, counters held),
# centred on the plate. Two 4 mm screw holes countersunk 8 mm, centred top to
# bottom, their centres 12 mm in from the left and right edges. An engraved
# border line 4 mm inside the plate's edge.

import "std/fasteners.aidl"

thickness 3 mm
param cap = 40 mm, min = 25, max = 50

solid sign {
    body = RoundedRectangle(center=(0, 0), width=200, height=80, corner_radius=8)
    hole letters {
        word = Text("LAB 3", (0, 0), size=cap, font="sans:Bold", valign="middle", stencil=true)
    }
    hole screws {
        l = Circle(center=(-100 + 12, 0), diameter=4)
        r = Circle(center=(100 - 12, 0), diameter=4)
    }
    Countersink(screws, diameter=8)
    CenterInside(border, body)
    drawing border {
        line = RoundedRectangle(center=(0, 0), width=200 - 8, height=80 - 8, corner_radius=4)
    }
    assert body.bb.width == 200 mm and body.bb.height == 80 mm, "plate 200 x 80"
    assert letters.word.size == 40 mm, "40 mm letters"
    assert abs(letters.bb.center_x - body.bb.center_x) < 0.5 mm, "letters centred"
    assert screws.l.center.x - body.bb.left == 12 mm, "left screw 12 in"
    assert body.bb.right - screws.r.center.x == 12 mm, "right screw 12 in"
    assert letters.bb.right < screws.r.center.x - 4 mm - 3 mm, "letters clear the screw heads"
}
