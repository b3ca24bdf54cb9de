# Request (sport): a press that keeps a wooden tennis racket's head flat in storage,
# 6 mm plywood.
# - Two identical frames 280 x 340 mm, corners R30, clamping the racket head between them.
# - An elliptical window 200 x 260 mm in the middle of each (the press bears on the
#   head's rim only).
# - Four M6 carriage bolts with wing nuts, one in each corner, 25 mm in from both edges.
# - A carrying slot 100 x 18 mm centred 150 mm above the centre.
# - The front frame engraved COURT PRESS, filled, bold serif 14 mm, centred 150 mm below
#   the centre.
# - In 3D: the racket's frame, 20 mm thick, lies between the two frames.

import "std/fasteners.aidl"

thickness 6 mm

def press_frame(label=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=280, height=340, corner_radius=30)
    hole window { e = Ellipse(center=(0, 0), rx=100, ry=130) }
    hole handle { s = Slot(center=(0, 150), length=100, width=18) }
    bolt = clearance_hole(size=6)
    bolts = CornerPattern(bolt, body, inset=25)
    if label {
        drawing name {
            t = Text("COURT PRESS", position=(0, -150), size=14, font="serif:Bold",
                     valign="middle", fill=true)
        }
    }
}

assembly press {
    front = press_frame(label=true)
    back = press_frame()
    RightOf(back, front, gap=10)
    AlignCenterY(back, front)

    # in 3D: lying flat, the racket head (20 mm) between the frames
    Place(back, position=(0, 0, 6), face="down", up="back")
    Place(front, position=(0, 0, 26), face="up", up="back")

    assert front.body.bb.width == 280 mm and front.body.bb.height == 340 mm, "280 x 340"
    assert front.window.e.rx * 2 == 200 mm and front.window.e.ry * 2 == 260 mm, "window 200 x 260"
    assert len(front.bolts) == 4, "four bolts"
    assert front.bolts[0].c.center.x - front.body.bb.left == 25 mm and
        front.bolts[0].c.center.y - front.body.bb.bottom == 25 mm, "25 in from both edges"
    assert front.handle.s.length == 100 mm and front.handle.s.width == 18 mm, "slot 100 x 18"
    assert front.handle.s.center.y - front.body.center.y == 150 mm, "slot 150 above the centre"
    assert front.body.center.y - front.name.t.position.y == 150 mm, "name 150 below the centre"
    assert distance(front.name.t, front.bolts[0]) >= 5 mm, "name clear of the bolts"
}
