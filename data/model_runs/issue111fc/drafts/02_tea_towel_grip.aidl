# Request: a wall-mounted "ball grip" tea towel holder, 6 mm ply, five glued layers
# 90 x 130 mm with 10 mm corner radii. A towel corner pushed up into an 8 mm wide
# mouth (open at the bottom edge, 80 mm tall) lifts a 16 mm glass marble up a
# sloping ramp; pulled down, the marble rolls back and pinches the towel. Layers:
# a plain back plate; three spacers each cut with the mouth and the ramp (a slot
# 17 mm wide = marble + 1 mm, from its low end centred 5 mm right of the mouth's
# centre line and 45 mm up, to 20 mm right and 75 mm up), so the marble at the
# bottom of the ramp comes to 1 mm from the far wall of the mouth; a front plate
# with the mouth only (the marble cannot pass it) and "TEA TOWEL" engraved above it.
# Two M4 countersunk screws 50 mm apart, 105 mm up, through all five layers.

units mm
thickness 6 mm
import "std/fasteners.aidl"

W = 90 mm
H = 130 mm
R = 10 mm
BALL = 16 mm
MOUTH = 8 mm
MOUTH_H = 80 mm

def screws_and_body() -> solid {
    body = RoundedRectangle(center=(0, H / 2), width=W, height=H, corner_radius=R)
    left_screw = clearance_hole(size=4, cx=-25 mm, cy=105 mm)
    right_screw = clearance_hole(size=4, cx=25 mm, cy=105 mm)
}

def spacer() -> solid {
    body = RoundedRectangle(center=(0, H / 2), width=W, height=H, corner_radius=R)
    left_screw = clearance_hole(size=4, cx=-25 mm, cy=105 mm)
    right_screw = clearance_hole(size=4, cx=25 mm, cy=105 mm)
    hole mouth { m = Rectangle(bottom_left=(-MOUTH / 2, -1), width=MOUTH, height=MOUTH_H + 1) }
    hole ramp { r = Slot(start=(5, 45), end=(20, 75), width=BALL + 1 mm) }
}

assembly tea_towel_grip {
    back = screws_and_body()
    s1 = spacer()
    s2 = spacer()
    s3 = spacer()

    solid front {
        body = RoundedRectangle(center=(0, H / 2), width=W, height=H, corner_radius=R)
        left_screw = clearance_hole(size=4, cx=-25 mm, cy=105 mm)
        right_screw = clearance_hole(size=4, cx=25 mm, cy=105 mm)
        hole mouth { m = Rectangle(bottom_left=(-MOUTH / 2, -1), width=MOUTH, height=MOUTH_H + 1) }
        Countersink([left_screw, right_screw], diameter=8.5 mm)
        drawing label { t = Text("TEA TOWEL", position=(0, 88), size=7) }
    }

    # flat: a row of five
    RightOf(s1, back, gap=5)
    AlignBottom(s1, back)
    RightOf(s2, s1, gap=5)
    AlignBottom(s2, back)
    RightOf(s3, s2, gap=5)
    AlignBottom(s3, back)
    RightOf(front, s3, gap=5)
    AlignBottom(front, back)

    # 3D: stacked off the wall (the wall at y = 0), all facing the room
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(s1, position=(0, -6, 0), face="front", up="up")
    Place(s2, position=(0, -12, 0), face="front", up="up")
    Place(s3, position=(0, -18, 0), face="front", up="up")
    Place(front, position=(0, -24, 0), face="front", up="up")

    assert front.body.width == 90 mm and front.body.height == 130 mm, "layers 90 x 130"
    assert s1.mouth.m.width == 8 mm, "mouth 8 mm wide"
    assert s1.mouth.m.bb.top - s1.body.bb.bottom == 80 mm, "mouth 80 mm tall"
    assert s1.ramp.r.width == 16 mm + 1 mm, "ramp = marble + 1 mm"
    assert s1.ramp.r.start.x - 16 mm / 2 == -8 mm / 2 + 1 mm, "marble at rest 1 mm from the mouth's far wall"
    assert s1.ramp.r.end.y - s1.body.bb.bottom == 75 mm, "ramp's top 75 mm up"
    assert front.right_screw.c.center.x - front.left_screw.c.center.x == 50 mm, "screws 50 apart"
    assert front.left_screw.c.center.y - front.body.bb.bottom == 105 mm, "screws 105 mm up"
    assert distance(front.label, front.mouth) >= 2 mm, "label clear of the mouth"
}
