# Drill bit index for the workshop wall: a 200 x 60 mm plate with R5 corners, 3 mm plywood.
# Thirteen holes for drill bits 1.0 to 7.0 mm in 0.5 mm steps, each hole 0.2 mm over its bit,
# centers 12 mm apart on a row 24 mm above the bottom edge, the row's middle hole on the
# plate's center line. Each bit's size engraved 3.5 mm tall, centered 10 mm below its hole.
# "DRILL BITS" engraved 6 mm tall, its top 8 mm below the top edge, centered. Two 4.5 mm
# wall-screw holes countersunk 9 mm, 10 mm in from the left and right edges at mid-height.
units mm
thickness 3 mm

param pitch = 12 mm, min = 11 mm, max = 13 mm
param count = 13, min = 13, max = 13

solid index {
    body = RoundedRectangle(center=(0, 0), width=200, height=60, corner_radius=5)

    hole bits {
        for i in range(count) {
            h = Circle(center=((i - 6) * pitch, -6), diameter=1.0 + i * 0.5 + 0.2)
        }
    }

    drawing labels {
        for i in range(count) {
            t = Text(str(1.0 + i * 0.5), position=((i - 6) * pitch, -16), size=3.5,
                     valign="middle")
        }
        title = Text("DRILL BITS", position=(0, 22), size=6, valign="top")
    }

    hole screws {
        left = Circle(center=(-90, 0), diameter=4.5)
        right = Circle(center=(90, 0), diameter=4.5)
    }
    Countersink(screws, diameter=9)

    assert body.bb.width == 200 mm and body.bb.height == 60 mm, "plate 200 x 60 mm"
    assert len(bits.h) == 13, "thirteen bit holes"
    assert bits.h[0].diameter == 1.2 mm, "first hole: 1.0 mm bit + 0.2 mm"
    assert bits.h[12].diameter == 7.2 mm, "last hole: 7.0 mm bit + 0.2 mm"
    assert bits.h[1].center.x - bits.h[0].center.x == 12 mm, "centers 12 mm apart"
    assert bits.h[0].center.y - body.bb.bottom == 24 mm, "row 24 mm above the bottom edge"
    assert bits.h[6].center.x == body.center.x, "middle hole on the center line"
    assert bits.h[6].center.y - labels.t[6].center.y == 10 mm, "labels 10 mm below the holes"
    assert body.bb.top - labels.title.bb.top == 8 mm, "title top 8 mm below the top edge"
    assert screws.left.center.x - body.bb.left == 10 mm, "screw 10 mm in from the left"
    assert body.bb.right - screws.right.center.x == 10 mm, "screw 10 mm in from the right"
}
