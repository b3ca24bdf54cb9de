# Request: a wall rack for the kitchen that holds my three 30 cm rolls -- cling film, foil and
# baking paper -- each on a 12 mm dowel through its core, so I can pull off a sheet one-handed.
# 6 mm ply. Two end plates, 110 mm deep x 200 mm tall, rounded 15 mm at the front corners,
# each with three cradle slots 12.5 mm wide that run in from the front edge sloping down at
# 30 deg toward the wall, so the dowel rolls to the bottom and rests 60 mm out from the wall;
# the dowels 60 mm apart in height (the lowest 30 mm up). The name of each roll engraved on
# the outside of each end plate under its cradle. A back board 190 mm tall between the end
# plates, leaving 310 mm for the rolls (300 mm long plus 5 mm play each end), glued into the
# end plates with two 40 mm tenons each side, and screwed to the wall through two countersunk
# M4 holes (8 mm heads) 30 mm below its top edge and 35 mm in from its ends.

units mm
thickness 6 mm
import "std/joints.aidl"
import "std/fasteners.aidl"

T = 6 mm
DEPTH = 110 mm
HEIGHT = 200 mm
INNER = 310 mm
NAMES = ["FOIL", "CLING FILM", "BAKING PAPER"]

# an end plate in side view: x = s * distance from the wall (s = -1: the left plate, whose
# outside is seen from the left), y = height above the bottom
def end_plate(s=1) -> solid {
    body = RoundedRectangle(center=(s * DEPTH / 2, HEIGHT / 2), width=DEPTH, height=HEIGHT,
                            corner_radii=[0, 15, 15, 0] if s > 0 else [15, 0, 0, 15])
    hole cradle {
        for i in range(3) {
            c = Slot(start=(s * 60, 30 + 60 * i), end=(s * 125, 30 + 60 * i + 65 * tan(30 deg)),
                     width=12.5)
        }
    }
    joint = tab_and_slot(part="slot", length=190, thickness=T, tabs=2, tab=40, screw=0,
                         rotation=90 deg, cx=s * T / 2, cy=HEIGHT / 2)
    drawing labels {
        for i in range(3) {
            t = Text(NAMES[i], position=(s * 88, 30 + 60 * i - 10), size=6, max_width=36)
        }
    }
}

assembly wrap_rack {
    left = end_plate(s=-1)
    right = end_plate(s=1)

    solid back {
        body = Rectangle(center=(0, HEIGHT / 2), width=INNER + 2 * T, height=190)
        left_tenons = tab_and_slot(part="tab", length=190, thickness=T, tabs=2, tab=40, screw=0,
                                   rotation=90 deg, cx=-(INNER / 2 + T), cy=HEIGHT / 2)
        right_tenons = tab_and_slot(part="tab", length=190, thickness=T, tabs=2, tab=40, screw=0,
                                    rotation=-90 deg, cx=INNER / 2 + T, cy=HEIGHT / 2)
        screw_l = clearance_hole(size=4, cx=-(INNER / 2 - 35), cy=HEIGHT / 2 + 95 - 30)
        screw_r = clearance_hole(size=4, cx=INNER / 2 - 35, cy=HEIGHT / 2 + 95 - 30)
        Countersink([screw_l, screw_r], diameter=8)
    }

    # on the sheet: end plates either side of the back board
    LeftOf(left, back, gap=10)
    RightOf(right, back, gap=10)
    AlignBottom(left.body, back.body)
    AlignBottom(right.body, back.body)

    # in 3D: x along the wall, y out from the wall, z up; the back board against the wall
    Place(back, position=(0, T, 0), rotation=(90 deg, 0, 0))
    Place(left, position=(-INNER / 2, 0, 0), rotation=(90 deg, 0, -90 deg))
    Place(right, position=(INNER / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    # the request's numbers
    assert right.body.bb.width == 110 mm and right.body.bb.height == 200 mm, "end plate 110 x 200"
    assert back.body.bb.height == 190 mm, "back board 190 tall"
    assert back.body.bb.width - 2 * T == 310 mm, "310 mm for the rolls"
    assert right.cradle.c[0].start.x - right.body.bb.left == 60 mm, "dowel rests 60 mm out"
    assert left.body.bb.right - left.cradle.c[0].start.x == 60 mm, "dowel rests 60 mm out (left)"
    assert right.cradle.c[1].start.y - right.cradle.c[0].start.y == 60 mm, "dowels 60 apart"
    assert right.cradle.c[0].start.y - right.body.bb.bottom == 30 mm, "lowest dowel 30 up"
    assert right.cradle.c[0].width == 12.5 mm, "slot 12.5 wide"
    assert back.body.bb.top - back.screw_l.c.center.y == 30 mm, "screws 30 below the top"
    assert back.screw_l.c.center.x - (back.body.bb.left + T) == 35 mm, "screws 35 in"
    assert len(NAMES) == 3, "three rolls"
}
