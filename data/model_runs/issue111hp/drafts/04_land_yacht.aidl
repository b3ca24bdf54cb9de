# Request (toys): a wind-powered land yacht for a kids' race across the hall floor in front
# of a fan, in 3 mm ply. A T-shaped chassis: a spine 200 long x 30 wide with a round nose,
# and a rear cross-beam 140 wide x 25 long at its back end. Three wheels 50 mm across, each
# two glued discs with five 10 mm lightening holes, glued onto 4 mm dowel axles (4.0 mm
# holes) that turn in axle brackets (4.6 mm holes, 30 mm below the chassis' underside, so
# the wheels clear the chassis). Brackets 20 wide, round-bottomed, each glued up into the
# chassis on one 12 mm tab: two under the cross-beam 110 apart (wheels outside them), two
# at the front 13 apart with the front wheel between them, 25 mm behind the nose. A 6.2 mm
# hole for a 6 mm dowel mast 70 mm behind the nose. A sail of 0.5 mm card: a right triangle
# 180 tall along the mast and 110 along the foot, five 3 mm lacing holes 5 mm in from the
# mast edge, and a big "7" engraved.

import "std/joints.aidl"

thickness 3 mm

def axle_bracket() -> solid {
    # y = 0: the chassis' underside; the tab's tip at y = 3 (the chassis' top)
    plate = RoundedRectangle(bottom_left=(-10, -40), width=20, height=43,
                             corner_radii=[0, 0, 10, 10])
    top = tab_and_slot(part="tab", length=20 mm, thickness=3 mm, tabs=1, tab=12 mm, screw=0,
                       cx=0 mm, cy=3 mm)
    hole axle { c = Circle(center=(0, -30), diameter=4.6) }
}

def wheel_disc() -> solid {
    rim = Circle(center=(0, 0), diameter=50)
    hole axle { c = Circle(center=(0, 0), diameter=4.0) }
    hole light { c = Circle(center=(15, 0), diameter=10) }
    CircularPattern(light, 5, rim.center)
}

# x along the chassis from its back end, y across it
bx = [12.5, 12.5, 175, 175]
by = [55, -55, 6.5, -6.5]
# wheels: 2 discs on each rear axle end outside the brackets, 2 between the front brackets;
# their bottom faces' y (a part facing "front" has its bottom face on its +y side)
wx = [12.5, 12.5, 12.5, 12.5, 175, 175]
wy = [60.5, 63.5, -57.5, -60.5, 0, 3]

assembly yacht {
    solid chassis {
        spine = RoundedRectangle(bottom_left=(0, -15), width=200, height=30,
                                 corner_radii=[0, 15, 15, 0])
        beam = Rectangle(bottom_left=(0, -70), width=25, height=140)
        hole mast { c = Circle(center=(130, 0), diameter=6.2) }
        for i in range(4) {
            s = tab_and_slot(part="slot", length=20 mm, thickness=3 mm, tabs=1, tab=12 mm,
                             screw=0, cx=bx[i] * 1 mm, cy=by[i] * 1 mm)
        }
        Fixed(spine)
        Fixed(beam)
    }

    for i in range(4) {
        br = axle_bracket()
        br.bb.center == (240 + i * 25, 60)
        Place(br, position=(bx[i], by[i] + 1.5, 55), face="front", up="up")
    }

    for i in range(6) {
        wh = wheel_disc()
        wh.bb.center == (240 + (i % 3) * 55, -(i // 3) * 55)
        Place(wh, position=(wx[i], wy[i], 25), face="front", up="up")
    }

    solid sail {
        thickness 0.5 mm
        cloth = Polygon([(0, 0), (0, 180), (-110, 0)])
        hole lacing {
            for i in range(5) {
                c = Circle(center=(-5, 20 + i * 35), diameter=3)
            }
        }
        drawing number {
            n = Text("7", position=(-30, 30), size=30, font="sans:Bold", fill=true)
        }
    }
    sail.bb.bottom_left == (420, -70)

    Place(chassis, position=(0, 0, 55), face="up")
    Place(sail, position=(126, 0, 80), face="front", up="up")

    # the request's numbers
    assert chassis.spine.bb.width == 200 mm and chassis.spine.bb.height == 30 mm, "spine 200 x 30"
    assert chassis.beam.bb.height == 140 mm and chassis.beam.bb.width == 25 mm, "beam 140 x 25"
    assert chassis.spine.bb.right - chassis.mast.c.center.x == 70 mm, "mast 70 behind the nose"
    assert chassis.spine.bb.right - bx[2] * 1 mm == 25 mm, "front brackets 25 behind the nose"
    assert (by[0] - by[1]) * 1 mm == 110 mm, "rear brackets 110 apart"
    assert (by[2] - by[3]) * 1 mm == 13 mm, "front brackets 13 apart"
    assert br[0].top.bb.top - br[0].axle.c.center.y == 30 mm + 3 mm, "axle 30 below the underside"
    assert 30 mm - wh[0].rim.radius >= 3 mm, "wheels clear the chassis"
    assert wh[0].rim.diameter == 50 mm, "wheels 50 across"
    assert len(wh) == 6, "three wheels of two discs"
    assert (by[2] - by[3]) * 1 mm - 3 mm - 6 mm >= 3 mm, "front wheel turns between its brackets"
    assert 70 mm - (wy[1] * 1 mm) >= 3 mm, "rear wheels under the beam's ends"
    assert sail.cloth.bb.height == 180 mm and sail.cloth.bb.width == 110 mm, "sail 180 x 110"
    assert len(sail.lacing.c) == 5, "five lacing holes"
    assert -sail.lacing.c[0].center.x == 5 mm, "lacing 5 mm in from the mast edge"
}
