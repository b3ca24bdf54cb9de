# Request: a floor stand that holds a bike upright by a wheel (26" to 29", tyres up to 60 mm),
# from 9 mm birch ply, flat-pack with no glue or screws.
# - Two side plates 440 mm long, 160 mm tall at the ends, the top edge a curve dipping to 70 mm
#   in the middle, top corners R15; they stand 65 mm apart (inside) and grip the tyre.
# - Two feet 300 mm long x 55 mm tall (top corners R10) across under them, 195 mm either side of
#   the middle, cross-halved into the plates (half the foot's height each).
# - "BIKE PARK" engraved (bold, 22 mm, filled) on the outer face of the front plate.
# - A 29" wheel (radius 340 mm) standing on the floor between the plates must clear the feet.

import "std/joints.aidl"

thickness 9 mm

T = 9 mm
GAP = 65 mm          # inside, between the plates
Y_MID = GAP / 2 + T / 2
FX = 195 mm          # the feet's middle planes
FOOT_H = 55 mm
R_WHEEL = 340 mm

def side_plate() -> solid {
    bottom = Line((-220, 0), (220, 0))
    right = Line((220, 0), (220, 160))
    # the arc meets the ends at about 45 deg: a R15 fillet there took 18 mm off the ends'
    # height (W0405); a 40 mm flat at 160 before the curve gives square corners to round
    flat_r = Line((220, 160), (180, 160))
    top = Arc(start=(180, 160), through=(0, 70), end=(-180, 160))
    flat_l = Line((-180, 160), (-220, 160))
    left = Line((-220, 160), (-220, 0))
    Fillet(right.end, 15)
    Fillet(left.start, 15)
    slot_l = cross_halving(depth=FOOT_H / 2, thickness=T, rotation=180 deg, cx=-FX, cy=0 mm)
    slot_r = cross_halving(depth=FOOT_H / 2, thickness=T, rotation=180 deg, cx=FX, cy=0 mm)
}

def foot() -> solid {
    body = RoundedRectangle(center=(0, FOOT_H / 2), width=300, height=FOOT_H,
                            corner_radii=[10, 10, 0, 0])
    slot_f = cross_halving(depth=FOOT_H / 2, thickness=T, cx=-Y_MID, cy=FOOT_H)
    slot_b = cross_halving(depth=FOOT_H / 2, thickness=T, cx=Y_MID, cy=FOOT_H)
}

assembly bike_stand {
    front = side_plate()
    back = side_plate()
    foot_l = foot()
    foot_r = foot()

    drawing label {
        t = Text("BIKE PARK", position=(0, 30), size=22, font="sans:Bold", fill=true,
                 valign="middle")
    }
    CutInto(label, front)

    # flat layout
    Above(back, front, gap=10)
    AlignLeft(back, front)
    Below(foot_l, front, gap=10)
    AlignLeft(foot_l, front)
    RightOf(foot_r, foot_l, gap=10)
    AlignTop(foot_r, foot_l)

    # 3D: plates upright along x, the engraved face to the front; feet across at x = +-FX
    Place(front, position=(0, -GAP / 2, 0), face="front", up="up")
    Place(back, position=(0, GAP / 2, 0), face="back", up="up")
    Place(foot_l, position=(-FX - T / 2, 0, 0), face="right", up="up")
    Place(foot_r, position=(FX - T / 2, 0, 0), face="right", up="up")

    # the request's numbers
    assert front.bottom.length == 440 mm, "plates 440 long"
    assert front.right.length == 160 mm, "160 tall at the ends"
    assert front.bb.top - front.top.through.y == 160 mm - 70 mm, "dips to 70 in the middle"
    assert 2 * Y_MID - T == 65 mm, "65 mm between the plates"
    assert foot_l.body.bb.width == 300 mm and foot_l.body.bb.height == 55 mm, "feet 300 x 55"
    assert 2 * FX == 390 mm, "feet 195 either side of the middle"
    assert R_WHEEL - sqrt(R_WHEEL ** 2 - (FX - T / 2) ** 2) > FOOT_H,
        "a 29-inch wheel on the floor clears the feet"
}
