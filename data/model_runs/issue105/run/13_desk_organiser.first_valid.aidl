# Desk organiser front panel: 240 mm wide x 100 mm tall, 3 mm plywood, finger joints
# (10 mm fingers) on the left, right and bottom edges, top edge flat; a row of three
# 16 mm pen holes 25 mm apart, centred 30 mm below the top edge on the left third; a
# 70 mm x 12 mm rounded business-card slot centred on the right third, 30 mm below the top;
# a 30 mm wide x 15 mm deep finger notch (half-round ends) in the middle of the top edge.
import "std/joints.aidl"

thickness 3 mm

solid panel {
    body = finger_panel(width=240 mm, height=100 mm, thickness=3 mm, finger=10 mm, top="flat")

    hole pen {
        c = Circle(center=(-105, 20), diameter=16)
    }
    pens = LinearPattern(pen, 3, (25, 0))
    pens[1].c.center.x == body.outline.center.x - 80
    pen.c.center.y == body.outline.top.midpoint.y - 30

    hole card {
        s = Slot(center=(80, 20), length=70, width=12)
    }
    At(card.s.center, body.outline.center, dx=80, dy=20)

    hole notch {
        s = Slot(center=(0, 50), length=30, width=30)
    }
    AlignCenterX(notch, body.outline)
    notch.s.center.y == body.outline.top.midpoint.y
}
