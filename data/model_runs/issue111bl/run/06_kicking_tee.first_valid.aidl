# Request (sport): a football kicking tee, 6 mm ply. Two plates 120 mm wide cross-halve at their
# middles (one slotted 20 mm down from the top, the other 20 mm up from the bottom, 0.2 mm
# clearance). Their tops are a dip of the ball's own radius (size 5 ball, 220 mm across) whose
# lowest point is 40 mm above the ground, so the ball sits in all four cradles 40 mm up. Each plate
# has two 16 mm lightening holes, 38 mm either side of the middle and 24 mm up; the first plate has
# "CITY FC" engraved 7 mm tall in its middle, 10 mm up.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
ball_d = 220 mm
seat = 40 mm
plate_w = 120 mm
halving = 20 mm
ball_c = seat + ball_d / 2
end_a = acos((plate_w / 2) / (ball_d / 2))

def cradle() -> solid {
    top = Arc(center=(0, ball_c), radius=ball_d / 2, start_angle=180 deg + end_a,
              end_angle=360 deg - end_a)
    right = Line(top.end, (plate_w / 2, 0))
    bottom = Line((plate_w / 2, 0), (-plate_w / 2, 0))
    left = Line((-plate_w / 2, 0), top.start)
    Rigid(top, right, bottom, left)
    for x in [-38, 38] {
        hole light { c = Circle(center=(x, 24), diameter=16) }
    }
}

assembly tee {
    a = cradle()
    b = cradle()
    halve_a = cross_halving(depth=halving, thickness=t, clearance=0.2, cx=0, cy=seat)
    halve_b = cross_halving(depth=halving, thickness=t, clearance=0.2, rotation=180, cx=0, cy=0)
    CutInto(halve_a, a)
    CutInto(halve_b, b)
    drawing club { txt = Text("CITY FC", position=(0, 10), size=7, valign="middle") }
    CutInto(club, a)

    RightOf(b, a, gap=5)
    AlignBottom(b, a)
    Rigid(a, halve_a, club)
    Rigid(b, halve_b)

    Place(a, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(b, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 0))

    # the request's numbers
    assert a.bottom.length == 120 mm, "plates 120 wide"
    assert a.top.radius == 220 mm / 2, "dip of the ball's radius"
    assert a.top.center.y - a.top.radius - a.bottom.start.y == 40 mm, "ball 40 mm up"
    assert halve_a.cut.bb.top - halve_a.cut.bb.bottom == 20 mm, "top slot 20 deep"
    assert halve_b.cut.bb.top - b.bottom.start.y == 20 mm, "bottom slot 20 up"
    assert halve_a.cut.bb.center_x == a.top.center.x, "halving in the middle"
    assert a.light[1].c.center.x - a.top.center.x == 38 mm, "holes 38 out"
    assert a.light[1].c.center.y - a.bottom.start.y == 24 mm, "holes 24 up"
    assert club.txt.position.y - a.bottom.start.y == 10 mm, "name 10 up"
}
